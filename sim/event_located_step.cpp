#include "sim/event_located_step.h"

#include <cmath>
#include <limits>

namespace railjoint {

EventLocation impact_location(const SimSettings& settings, double speed_m_per_s, bool compliant) {
  EventLocation location;
  location.enabled = !compliant;
  location.solved_from_m = settings.contact_processing_threshold_m;
  location.closing_speed_m_per_s = kClosingSpeedFraction * speed_m_per_s;
  return location;
}

double closing_gap_beyond_solving_m(const std::vector<ContactSample>& contacts, const EventLocation& location) {
  double gap = std::numeric_limits<double>::infinity();
  for (const ContactSample& c : contacts) {
    if (c.normal_velocity_m_per_s < -location.closing_speed_m_per_s) {
      gap = std::min(gap, c.distance_m - location.solved_from_m);
    }
  }
  return gap;
}

LocatedStep step_locating_impacts(CrossingWorld& world, double dt_s, const std::vector<ContactSample>& contacts_at_start,
                                  const EventLocation& location) {
  const WorldState start = world.state();
  LocatedStep out;
  const auto take = [&](double dt) {
    world.restore(start);
    world.step(dt);
    out.dt_s = dt;
    out.sample = world.sample();
    out.contacts_now = world.probe_contacts();
    return closing_gap_beyond_solving_m(out.contacts_now, location);
  };
  const double tol = location.tolerance_m;
  const auto on_target = [tol](double gap) { return gap <= 0.0 && gap >= -tol; };
  const double gap_end = take(dt_s);
  if (!location.enabled) return out;
  const double gap_start = closing_gap_beyond_solving_m(contacts_at_start, location);
  // Located only when the contact was not yet solved at the start: one that
  // was is an impact under way (or a penetration), not a first touch.
  if (!(gap_end < -tol) || !(gap_start > 0.0)) return out;

  // Regula falsi (Illinois) on the step length towards the middle of the
  // target window: the gap is smooth in time along the approach (a line or
  // a pivot arc), so a handful of retries do.
  const double aim = -0.5 * tol;
  double lo = 0.0, hi = dt_s;
  double f_lo = (std::isfinite(gap_start) ? gap_start : tol) - aim;
  double f_hi = gap_end - aim;
  int side = 0;
  for (int i = 0; i < 60 && hi - lo > 1e-15; ++i) {
    double dt = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
    if (!(dt > lo && dt < hi)) dt = 0.5 * (lo + hi);
    const double gap = take(dt);
    if (on_target(gap)) {
      out.located = true;
      return out;
    }
    const double f = (std::isfinite(gap) ? gap : tol) - aim;
    if (f > 0.0) {  // not solved yet: the touch lies later
      lo = dt;
      f_lo = f;
      if (side == -1) f_hi *= 0.5;
      side = -1;
    } else {
      hi = dt;
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
