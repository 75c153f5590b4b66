#pragma once
// Force scenes the sim tests share, and the bridge from a force run's model
// to the independent lumped-track reference (lumped_track_reference.h).

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

#include "sim/crossing_model.h"
#include "sim/setting_checks.h"
#include "tests/sim/lumped_track_reference.h"

namespace railjoint {

/// A force run on the discrete track `track`: the square dipped joint (beta
/// 0.03), a thin disc at y = 0, the defaults' wheel at speed v, started
/// `approach_m` before the impact, on rails as long as the run needs,
/// stepped at `force_time_step_s` (empty: the default).
inline CrossingModel discrete_track_model(double v, const DiscreteTrackSettings& track, double approach_m,
                                          std::optional<double> force_time_step_s = std::nullopt) {
  JointParams joint;
  joint.theta_rad = 0.5 * std::numbers::pi;
  WheelParams wheel;
  wheel.lateral_m = 0.0;
  wheel.speed_m_per_s = v;
  SimSettings settings;
  settings.approach_distance_m = approach_m;
  settings.make_inertial().contact.emplace<ElasticCrossingSettings>().discrete_track = track;
  if (force_time_step_s) settings.make_inertial().force_time_step_s = *force_time_step_s;
  joint.length_m = std::max(1.0, rail_length_needed_m(joint, wheel, settings));
  return build_crossing_model(joint, wheel, settings);
}

/// The same with the defaults' track and a hinge of `joint_N_m_per_rad` at
/// the joint (none: continuous rail).
inline CrossingModel discrete_track_model(double v, std::optional<double> joint_N_m_per_rad, double approach_m) {
  DiscreteTrackSettings track;
  track.joint_bending_stiffness_N_m_per_rad = joint_N_m_per_rad;
  return discrete_track_model(v, track, approach_m);
}

/// The reference's history of a force run on the default lumped track
/// (Hertz's constant 3.86e-8 R^-0.115, the README's): its joint, wheel and
/// static start, the rail ends at the simulated wheel's span's furthest and
/// nearest slices on the cut x = y cot(theta), reported at `times_s`.
inline testing_reference::ReferenceHistory lumped_reference_history(const CrossingModel& m,
                                                                     const std::vector<double>& times_s) {
  testing_reference::LumpedCrossing ref;
  ref.half_dip_slope = std::tan(0.5 * m.joint.beta_rad);
  ref.speed_m_per_s = m.wheel.speed_m_per_s;
  ref.hertz_constant = 3.86e-8 * std::pow(m.wheel.radius_m, -0.115);
  const LumpedTrackSettings track;
  ref.rail_mass_kg = track.rail_mass_kg;
  const double cot = std::cos(m.joint.theta_rad) / std::sin(m.joint.theta_rad);
  const double y_a = m.simulated_wheel.lateral_m - 0.5 * m.simulated_wheel.width_m;
  const double y_b = m.simulated_wheel.lateral_m + 0.5 * m.simulated_wheel.width_m;
  ref.incoming_end_x_m = std::max(y_a * cot, y_b * cot);
  ref.outgoing_start_x_m = std::min(y_a * cot, y_b * cot);
  const double W = ref.wheel_load_N + ref.wheel_mass_kg * ref.gravity;
  const double k_p = track.support.pad_stiffness_N_per_m, k_b = track.support.ballast_stiffness_N_per_m;
  const testing_reference::LumpedState start = {
      m.start.centre_m.z(), m.start.vertical_velocity_m_per_s, -W / k_p - W / k_b, 0.0, -W / k_b, 0.0};
  return testing_reference::integrate_lumped_crossing(ref, m.start.centre_m.x(), start, times_s);
}

}  // namespace railjoint
