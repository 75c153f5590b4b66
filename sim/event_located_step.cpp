#include "sim/event_located_step.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace railjoint {

EventLocation impact_location(const SimSettings& settings, double speed_m_per_s, bool compliant) {
  EventLocation location;
  location.enabled = !compliant;
  location.solved_from_m = settings.contact_processing_threshold_m;
  location.tolerance_m = std::max(1e-12, std::abs(settings.contact_processing_threshold_m));
  location.closing_speed_m_per_s = kClosingSpeedFraction * speed_m_per_s;
  return location;
}

RailGaps closing_gaps_beyond_solving_m(const std::vector<ContactSample>& contacts, const EventLocation& location,
                                       RailsInContact engaged) {
  RailGaps gaps;
  gaps.fill(std::numeric_limits<double>::infinity());
  for (const ContactSample& c : contacts) {
    if (c.rail_index < 0 || c.rail_index >= kMaxRails || engaged.has(c.rail_index)) continue;
    if (c.normal_velocity_m_per_s < -location.closing_speed_m_per_s) {
      double& gap = gaps[static_cast<std::size_t>(c.rail_index)];
      gap = std::min(gap, c.distance_m - location.solved_from_m);
    }
  }
  return gaps;
}

namespace {

// The rail whose contact crossed the solving gap earliest between two
// configurations `before` and `after` (by linear interpolation of each gap),
// or -1 if none crossed beyond the tolerance.
int first_crossing(const RailGaps& before, const RailGaps& after, double tolerance_m) {
  int first = -1;
  double first_fraction = 2.0;
  for (std::size_t r = 0; r < before.size(); ++r) {
    if (!(before[r] > 0.0) || !(after[r] < -tolerance_m)) continue;
    const double fraction = std::isfinite(before[r]) ? before[r] / (before[r] - after[r]) : 0.0;
    if (fraction < first_fraction) {
      first_fraction = fraction;
      first = static_cast<int>(r);
    }
  }
  return first;
}

// The closing gaps, and a contact that closed, went past the solving gap
// and turned to open again within the step (a flight grazing a rail whose
// path bends away under it): it ends the step opening but inside the rail,
// and crossed too (a coarse step of a flight over a curved dip ended 1.1 um
// deep). At a step's start such a contact is an impact under way.
RailGaps crossing_gaps(const std::vector<ContactSample>& contacts, const EventLocation& location,
                       RailsInContact engaged) {
  RailGaps gaps = closing_gaps_beyond_solving_m(contacts, location, engaged);
  for (const ContactSample& c : contacts) {
    if (c.rail_index < 0 || c.rail_index >= kMaxRails || engaged.has(c.rail_index)) continue;
    const double beyond_m = c.distance_m - location.solved_from_m;
    double& gap = gaps[static_cast<std::size_t>(c.rail_index)];
    if (beyond_m < -location.tolerance_m) gap = std::min(gap, beyond_m);
  }
  return gaps;
}

}  // namespace

LocatedStep step_locating_impacts(CrossingWorld& world, double dt_s, const std::vector<ContactSample>& contacts_at_start,
                                  const EventLocation& location, RailsInContact engaged) {
  const WorldState start = world.state();
  LocatedStep out;
  const auto take = [&](double dt) {
    world.restore(start);
    world.step(dt);
    out.dt_s = dt;
    out.sample = world.sample();
    out.contacts_now = world.probe_contacts();
    return crossing_gaps(out.contacts_now, location, engaged);
  };
  const double tol = location.tolerance_m;
  const RailGaps gaps_end = take(dt_s);
  if (!location.enabled) return out;
  // Located only on a rail whose contact was not yet solved at the start:
  // one that was is an impact under way (or a penetration), not a first touch.
  RailGaps gaps_lo = crossing_gaps(contacts_at_start, location, engaged);
  int target = first_crossing(gaps_lo, gaps_end, tol);
  if (target < 0) return out;

  // Regula falsi (Illinois) on the step length, aiming at the middle of the
  // target window for the rail that crosses first: each gap is smooth in
  // time along the approach (a line or a pivot arc), so a handful of retries
  // do. Should another rail turn out to cross before it inside the shortened
  // step, that one becomes the target.
  const double aim = -0.5 * tol;
  const auto value = [&](const RailGaps& gaps) {
    const double g = gaps[static_cast<std::size_t>(target)];
    return (std::isfinite(g) ? g : tol) - aim;
  };
  double lo = 0.0, hi = dt_s;
  RailGaps gaps_hi = gaps_end;
  double f_lo = value(gaps_lo);
  double f_hi = value(gaps_hi);
  int side = 0;
  for (int i = 0; i < 60 && hi - lo > 1e-15; ++i) {
    double dt = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
    if (!(dt > lo && dt < hi)) dt = 0.5 * (lo + hi);
    const RailGaps gaps = take(dt);
    const int earlier = first_crossing(gaps_lo, gaps, tol);
    if (earlier >= 0 && earlier != target) {
      target = earlier;
      hi = dt;
      gaps_hi = gaps;
      f_lo = value(gaps_lo);
      f_hi = value(gaps_hi);
      side = 0;
      continue;
    }
    const double f = value(gaps);
    if (f <= 0.5 * tol && f >= -0.5 * tol) {  // the target's gap in [solved_from - tol, solved_from]
      out.located = true;
      return out;
    }
    if (f > 0.0) {  // not solved yet: the touch lies later
      lo = dt;
      gaps_lo = gaps;
      f_lo = f;
      if (side == -1) f_hi *= 0.5;
      side = -1;
    } else {
      hi = dt;
      gaps_hi = gaps;
      f_hi = f;
      if (side == +1) f_lo *= 0.5;
      side = +1;
    }
  }
  // Not to tolerance (the gap jumps at this scale): end just past the
  // solving gap, so the contact is solved in the next step and no step repeats.
  take(hi);
  out.located = true;
  return out;
}

}  // namespace railjoint
