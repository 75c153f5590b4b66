#include "sim/step_control.h"

#include <algorithm>
#include <cmath>

#include "models/rail_top.h"

namespace railjoint {

RailsInContact RailsInContact::of(const WheelSample& sample) {
  return RailsInContact{solved_rails(sample)};
}

RailsInContact RailsInContact::of_last(const std::vector<WheelSample>& samples, std::size_t count) {
  RailsInContact out;
  for (std::size_t k = samples.size(); k > 0 && samples.size() - k < count; --k) out.mask |= of(samples[k - 1]).mask;
  return out;
}

namespace {
// The fine step: sim.refined_time_step, or an eighth of the pivot before a
// kinematic landing when that is shorter (never below 1/64 of the setting).
// The pivot turns the path from the incoming rail's slope at the corner to
// the predicted approach slope, an angle dphi about the corner: R dphi / v.
double fine_step_s(const CrossingModel& model) {
  const double refined_s = model.settings.refined_time_step_s;
  const ImpactPrediction& p = model.prediction;
  if (model.inertial() || !p.on_landing) return refined_s;
  const double v = model.wheel.speed_m_per_s;
  const double rail_slope = rail_surface_slope(model.joint, 0, p.contact_A_m.x());
  const double turn_rad = std::abs(std::atan(p.zdot_before_m_per_s / v) - std::atan(rail_slope));
  // A pivot whose whole change of vertical velocity is below 1e-6 of the
  // jump's cannot move the jump by more, resolved or not.
  if (v * turn_rad < 1e-6 * std::abs(p.zdot_after_m_per_s - p.zdot_before_m_per_s)) return refined_s;
  const double pivot_s = model.simulated_wheel.radius_m * turn_rad / v;
  return std::clamp(pivot_s / 8.0, refined_s / 64.0, refined_s);
}

// The step while the wheel turns about a contact: the fine step below
// kTurnReferenceSpeed_m_per_s stretched to turn the wheel by as much as it
// does at that speed, v dt / R. Where the fine step is shortened for a short
// pivot, that step; and where the load (`load_m_per_s2`, per unit mass)
// cannot hold the wheel on a corner, v^2 / R above it, the fine step: the
// wheel flies off the rail's end, from where the step that crosses it ends
// (a landing after such a flight moved by up to 1.6e-4 with turn steps).
double turn_step_s(const CrossingModel& model, double fine_s, double load_m_per_s2) {
  const double refined_s = model.settings.refined_time_step_s;
  const double v = model.wheel.speed_m_per_s;
  if (fine_s < refined_s || !(v < kTurnReferenceSpeed_m_per_s)) return fine_s;
  if (v * v / model.simulated_wheel.radius_m > load_m_per_s2) return fine_s;
  return refined_s * (kTurnReferenceSpeed_m_per_s / v);
}
}  // namespace

StepControl::StepControl(const CrossingModel& model, double vertical_external_force_N)
    : model_(model),
      fine_step_s_(fine_step_s(model)),
      flight_acceleration_m_per_s2_(std::abs(vertical_external_force_N) / model.wheel.mass_kg),
      turn_step_s_(turn_step_s(model, fine_step_s_, flight_acceleration_m_per_s2_)),
      // Fine from the start until the path is known.
      refine_until_s_(refine_hold_in_use_s(model.settings)),
      next_dt_s_(model.settings.time_step_s) {}

double StepControl::next_step_s(double time_s) const {
  if (time_s < refine_until_s_) return fine_step_s_;
  if (time_s < turn_until_s_) return std::min(turn_step_s_, next_dt_s_);
  return next_dt_s_;
}

void StepControl::after_step(const std::vector<WheelSample>& samples, double dt_s, bool located) {
  const SimSettings& settings = model_.settings;
  const double v = model_.wheel.speed_m_per_s;
  const WheelSample& now = samples.back();
  const WheelSample& before = samples[samples.size() - 2];
  engaged_ = RailsInContact::of_last(samples);

  const double hold_until_s = now.time_s + refine_hold_in_use_s(settings);
  const auto solved = [&](const ContactSample& c) { return c.distance_m <= settings.contact_processing_threshold_m; };
  // Turning about a contact: zdot changes while the wheel is on the rail (on
  // a plane it does not change at all). In flight zdot changes by the load's
  // acceleration every step; more than that, and more than 1e-4 v, is a strike
  // under way.
  const double dzdot = std::abs(now.velocity_m_per_s.z() - before.velocity_m_per_s.z());
  const bool in_contact = std::any_of(now.contacts.begin(), now.contacts.end(), solved);
  const bool struck = dzdot > 1e-4 * v + 2.0 * flight_acceleration_m_per_s2_ * dt_s;
  // Near the end of the incoming rail (at the contact's y) or the entry kink
  // of a flat approach: the first coarse step over it would leave the pivot
  // arc that follows (the step-down side lost the kinematic path and landed
  // 13 % harder at 2e-4 s).
  const double reach_m = 2.0 * v * settings.time_step_s;
  const double kink_x_m = -0.5 * model_.joint.length_m;
  const bool near_edge = std::any_of(now.contacts.begin(), now.contacts.end(), [&](const ContactSample& c) {
    if (c.rail_index != 0 || !solved(c)) return false;
    const double to_cut = cut_x_m(model_.joint, c.point_on_rail_m.y(), 0) - c.point_on_rail_m.x();
    const double to_kink = kink_x_m - c.point_on_rail_m.x();
    return to_cut < reach_m || (model_.flat_approach_m() > 0.0 && std::abs(to_kink) < reach_m);
  });
  // Just off a rail the solver held the wheel on (crossing_world.cpp): a
  // flight has begun whose landing on that rail is no located impact while
  // the rail counts as engaged, so a coarse step there would land it a coarse
  // step's fall deep (1.2 um at 1e-4 s).
  const bool left_rail = engaged_.mask != 0 && RailsInContact::of(now).mask == 0;
  // Turning about a contact the load holds the wheel on with a margin (the
  // contacts carry at least kTurnHeldLoadFraction of it) takes turn steps; a
  // contact near letting go (an inertial wheel about to lift off a corner)
  // fine ones, so the lift-off is found to the fine step.
  const bool turning = (in_contact && dzdot > 1e-5 * v) || near_edge;
  double contact_force_N = 0.0;
  for (const ContactSample& c : now.contacts) contact_force_N += c.impulse_Ns().z() / dt_s;
  const bool held = contact_force_N >= kTurnHeldLoadFraction * flight_acceleration_m_per_s2_ * model_.wheel.mass_kg;
  if (located || struck || left_rail || (turning && !held)) {
    refine_until_s_ = hold_until_s;
  } else if (turning) {
    turn_until_s_ = hold_until_s;
  }

  // Closing contacts: fine once one is within sim.refine_distance of the
  // gap the solver takes it from (a wheel hovering just above a corner it
  // barely holds on to, the last micrometres before a strike), and otherwise
  // on rails the wheel is not on a quarter of the time the nearest needs to
  // close. The recorded gap is from the step's start (Bullet detects, then
  // integrates).
  next_dt_s_ = settings.time_step_s;
  const double closing_speed_m_per_s = kClosingSpeedFraction * v;
  for (const ContactSample& c : now.contacts) {
    if (c.normal_velocity_m_per_s >= -closing_speed_m_per_s) continue;
    const double gap_now_m = c.distance_m - settings.contact_processing_threshold_m + c.normal_velocity_m_per_s * dt_s;
    if (gap_now_m < settings.refine_distance_m) {
      refine_until_s_ = hold_until_s;
    } else if (!engaged_.has(c.rail_index)) {
      next_dt_s_ = std::min(next_dt_s_, std::max(fine_step_s_, 0.25 * gap_now_m / -c.normal_velocity_m_per_s));
    }
  }
}

}  // namespace railjoint
