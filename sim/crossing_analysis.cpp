#include "sim/crossing_analysis.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "models/kinematic_trajectory.h"
#include "models/liftoff.h"
#include "sim/contact_phases.h"
#include "sim/force_contact_geometry.h"
#include "sim/force_peaks.h"
#include "sim/hertz_law.h"
#include "sim/impact_force_estimate.h"
#include "sim/lumped_track.h"
#include "sim/momentum_jump.h"
#include "sim/self_check.h"
#include "sim/track_support_forces.h"

namespace railjoint {

namespace {

// What every result carries, whatever the mode.
SimulationResult result_of(std::shared_ptr<const CrossingModel> model, CrossingRun& run) {
  SimulationResult result;
  result.steps = run.steps;
  result.refined_steps = run.refined_steps;
  result.max_penetration_m = run.max_penetration_m;
  result.trajectory = std::move(run.trajectory);
  result.model = std::move(model);
  return result;
}

// The velocity jumps of a rigid-contact run, also listed as the trajectory's impacts.
std::vector<MomentumJump> rigid_impacts(const CrossingModel& m, double vertical_external_force_N, Trajectory& trajectory) {
  const JumpDetection detection = jump_detection_for(m.wheel.mass_kg, m.wheel.speed_m_per_s, m.wheel.radius_m,
                                                     vertical_external_force_N, -m.settings.slop_m);
  std::vector<MomentumJump> jumps = find_momentum_jumps(trajectory, detection);
  for (const MomentumJump& jump : jumps) {
    ImpactEvent event;
    event.time_s = jump.time_s;
    event.wheel_x_m = jump.wheel_x_m;
    event.momentum_jump_Ns = jump.jump_Ns;
    event.contact_point_m = jump.struck_point_m;
    event.horizontal_impulse_Ns = jump.horizontal_impulse_Ns;
    event.first_sample = jump.first_sample;
    event.last_sample = jump.last_sample;
    trajectory.impacts.push_back(event);
  }
  return jumps;
}

// The joint's impact: the largest one within this distance of the predicted
// two-point contact (a 1 mm disc can give a small jump where its outer face
// passes a corner just before it), else the first one after that window
// opens (a wheel that flew over the joint). Landings on the incoming slope
// after a flight from the entry kink come earlier.
constexpr double kJointImpactWindow_m = 0.01;

// A compliant force pulse: the summed vertical contact force rises above
// this multiple of the static load somewhere in it; it extends either side
// while the force stays above the static load, so its impulse over that
// interval, sum (F - W) dt, is exactly the wheel's vertical momentum change.
constexpr double kPulseLoadFactor = 1.5;

std::vector<ImpactEvent> force_pulses(const Trajectory& trajectory, const std::vector<double>& force_N,
                                      double static_load_N) {
  const std::vector<WheelSample>& s = trajectory.samples;
  std::vector<ImpactEvent> pulses;
  std::size_t k = 1;
  while (k < s.size()) {
    if (force_N[k] <= kPulseLoadFactor * static_load_N) {
      ++k;
      continue;
    }
    std::size_t first = k;
    std::size_t last = k;
    while (first > 1 && force_N[first - 1] > static_load_N) --first;
    while (last + 1 < s.size() && force_N[last + 1] > static_load_N) ++last;
    ImpactEvent e;
    double impulse = 0.0;
    double horizontal = 0.0;
    double peak = -1.0;
    for (std::size_t j = first; j <= last; ++j) {
      const double dt = s[j].time_s - s[j - 1].time_s;
      impulse += (force_N[j] - static_load_N) * dt;
      for (const ContactSample& c : s[j].contacts) horizontal += c.impulse_Ns().x();
      if (force_N[j] > peak) {
        peak = force_N[j];
        e.time_s = s[j].time_s;
        e.wheel_x_m = s[j].centre_m.x();
        double largest = -1.0;
        for (const ContactSample& c : s[j].contacts) {
          if (c.impulse_Ns().z() > largest) {
            largest = c.impulse_Ns().z();
            e.contact_point_m = c.point_on_rail_m;
          }
        }
      }
    }
    e.momentum_jump_Ns = impulse;
    e.horizontal_impulse_Ns = horizontal;
    e.peak_force_N = peak;
    e.first_sample = first;
    e.last_sample = last;
    pulses.push_back(e);
    k = last + 1;
  }
  return pulses;
}

// A force run's P1 and P2 against Jenkins's, from the history the phases
// analysis summed (vertical_force_N, one value per sample).
ForceOutcome force_outcome(const CrossingModel& m, const CrossingRun& run, const Trajectory& trajectory,
                           const std::vector<double>& vertical_force_N, double static_N) {
  const ElasticCrossingSettings& elastic = *m.elastic();
  ForceOutcome f;
  f.hertz_constant_m_per_N2_3 = m.hertz_constant_m_per_N2_3;
  f.restitution = elastic.contact.restitution;
  f.track_model = elastic.track_model();
  f.suspension = elastic.vehicle.has_value();
  f.bogie = elastic.bogie.has_value();
  f.time_step_s = m.settings.inertial()->force_time_step_s;
  f.static_N = static_N;
  // The start's: its contact along a normal of vertical part n_z carries P0 / n_z.
  f.static_approach_m = hertz_approach_m(m.hertz_constant_m_per_N2_3, static_N / m.start_normal_z);
  f.static_rail_z_m = m.start_track.rail_z_m;
  f.static_sleeper_z_m = m.start_track.sleeper_z_m;
  f.start_force_N = run.start_contact_force_N;
  f.contact_force_N = vertical_force_N;
  f.track = run.track_states;
  f.energy_surplus_J = run.energy_surplus_J;
  const double turn_m_per_s = m.joint.beta_rad * m.wheel.speed_m_per_s;
  f.energy_scale_J = 0.5 * m.wheel.mass_kg * turn_m_per_s * turn_m_per_s + 0.5 * static_N * m.static_sink_m;

  std::vector<double> time_s;
  time_s.reserve(trajectory.samples.size());
  for (const WheelSample& s : trajectory.samples) time_s.push_back(s.time_s);
  JenkinsEstimate& j = f.jenkins;
  const double M = m.wheel.mass_kg;
  const double dip = m.joint.beta_rad;  // 2 alpha, the total dip angle
  const double v = m.wheel.speed_m_per_s;
  j.hertz_stiffness_N_per_m = linearised_hertz_stiffness_N_per_m(m.hertz_constant_m_per_N2_3, static_N);
  if (elastic.track) j.track = LumpedTrack::jenkins_equivalent(*elastic.track);
  if (elastic.discrete_track) j.track = run.discrete_track_equivalent;  // the run's own track's (elastic_crossing_run.cpp)
  // The P2 mode: wheel and track mass on K_T (none on a rigid track).
  const double mode_period_s =
      j.track ? 2.0 * std::numbers::pi * std::sqrt((M + j.track->track_mass_p2_kg) / j.track->track_stiffness_N_per_m)
              : 0.0;
  // The run's peaks and each wheel's own (one wheel: the run's).
  const auto wheel_of = [&](const ForcePeaks& p) {
    WheelForces w{{p.p1_N, p.p1_time_s, std::nullopt, p.p2_after_p1, p.flights, p.flight_time_s, p.longest_flight_s,
                   j.track && p.p2_across_flight},
                  std::nullopt};
    if (j.track) w.p2 = P2Peak{p.p2_N, p.p2_time_s, mode_period_s, p.p2_window_end_s, p.p2_window_covered};
    return w;
  };
  const ForcePeaks peaks = pick_force_peaks(time_s, vertical_force_N, static_N, kP2CutoffFrequency_Hz, mode_period_s);
  const WheelForces run_peaks = wheel_of(peaks);
  static_cast<ContactForcePeaks&>(f) = run_peaks;
  f.p1_pulse_steps = peaks.p1_pulse_steps;
  f.hertz_patches = force_hertz_patches(m.force_contact_inputs(), trajectory, f.p1_time_s,
                                        f.p2 ? std::optional<double>(f.p2->time_s) : std::nullopt);
  if (run.wheel_contact_force_N.empty()) f.wheels.push_back(run_peaks);
  for (const std::vector<double>& force_N : run.wheel_contact_force_N) {
    f.wheels.push_back(wheel_of(pick_force_peaks(time_s, force_N, static_N, kP2CutoffFrequency_Hz, mode_period_s)));
  }
  f.wheel_contact_force_N = run.wheel_contact_force_N;
  if (elastic.track) {
    // The lumped track's supports: the rail seat and the ballast (track_support_forces.h).
    const LumpedTrackSettings& lumped = *elastic.track;
    TrackSupportForces support = lumped_track_support_forces(time_s, run.track_states, lumped, kStandardGravity_m_per_s2);
    TrackSupportOutcome& o = f.support.emplace();
    o.rail_seat_static_N = static_N + lumped.rail_mass_kg * kStandardGravity_m_per_s2;
    o.ballast_static_N = static_N + (lumped.rail_mass_kg + lumped.support.sleeper_mass_kg) * kStandardGravity_m_per_s2;
    const auto largest = [&time_s](const std::vector<double>& force_N, double& peak_N, double& peak_time_s) {
      const auto top = std::max_element(force_N.begin(), force_N.end());
      if (top == force_N.end()) return;
      peak_N = *top;
      peak_time_s = time_s[static_cast<std::size_t>(top - force_N.begin())];
    };
    largest(support.rail_seat_N, o.rail_seat_peak_N, o.rail_seat_peak_time_s);
    largest(support.ballast_N, o.ballast_peak_N, o.ballast_peak_time_s);
    const ForcePeaks seat = pick_force_peaks(time_s, support.rail_seat_N, o.rail_seat_static_N, kP2CutoffFrequency_Hz,
                                             mode_period_s);
    o.p2_rail_seat_N = seat.p2_N;
    o.p2_rail_seat_time_s = seat.p2_time_s;
    f.wheels.front().p2_rail_seat = RailSeatP2{seat.p2_N, seat.p2_time_s, std::nullopt,
                                               -std::numeric_limits<double>::infinity(), seat.p2_window_end_s};
    o.rail_seat_N = std::move(support.rail_seat_N);
    o.ballast_N = std::move(support.ballast_N);
  }
  if (elastic.discrete_track) {
    // The discrete track's supports nearest the joint (elastic_crossing_run.cpp
    // records them, with their static forces under P0 on the joint): the
    // largest rail-seat and ballast forces over them, and each wheel's
    // rail-seat P2 within its own crossing (track_support_forces.h); the
    // run's is the leading wheel's, as its P1 and P2 are.
    f.support = discrete_track_support_outcome(time_s, run.supports);
    f.supports = run.supports;
    double window_start_s = -std::numeric_limits<double>::infinity();
    for (WheelForces& w : f.wheels) {
      const double window_end_s = w.p2 ? w.p2->window_end_s : time_s.back();
      w.p2_rail_seat = discrete_rail_seat_p2(time_s, run.supports, window_start_s, window_end_s, kP2CutoffFrequency_Hz);
      window_start_s = window_end_s;
    }
    if (f.support && f.wheels.front().p2_rail_seat) {
      f.support->p2_rail_seat_N = f.wheels.front().p2_rail_seat->force_N;
      f.support->p2_rail_seat_time_s = f.wheels.front().p2_rail_seat->time_s;
    }
  }
  // Jenkins's formulas are for a dip (2 alpha = beta): a step joint has none.
  // P2's damping bracket turns negative past a damping ratio of 2 / pi
  // (an overdamped track), where the first-order form no longer holds.
  if (m.joint.kind == JointKind::inclined) {
    j.p1_N = jenkins_p1_force_N(static_N, dip, v, j.hertz_stiffness_N_per_m, M,
                                j.track ? j.track->track_mass_p1_kg : std::numeric_limits<double>::infinity());
    if (j.track) {
      const JenkinsTrack& t = *j.track;
      const double bracket = 1.0 - t.track_damping_N_s_per_m * std::numbers::pi /
                                       (4.0 * std::sqrt(t.track_stiffness_N_per_m * (M + t.track_mass_p2_kg)));
      if (bracket > 0.0) {
        j.p2_N = jenkins_p2_force_N(static_N, dip, v, M, t.track_mass_p2_kg, t.track_stiffness_N_per_m,
                                    t.track_damping_N_s_per_m);
        // The calculator's bracket, 1 - C_T pi / sqrt(K_T m_T), for comparison where it is positive.
        if (t.track_damping_N_s_per_m * std::numbers::pi < std::sqrt(t.track_stiffness_N_per_m * t.track_mass_p2_kg)) {
          j.p2_calculator_N = jenkins_p2_calculator_form_N(static_N, dip, v, M, t.track_mass_p2_kg,
                                                           t.track_stiffness_N_per_m, t.track_damping_N_s_per_m);
        }
      }
    }
  }
  return f;
}

}  // namespace

SimulationResult analyse_kinematic_crossing(std::shared_ptr<const CrossingModel> model, CrossingRun run) {
  const CrossingModel& m = *model;
  SimulationResult result = result_of(std::move(model), run);
  Trajectory& trajectory = result.trajectory;
  const double v = m.wheel.speed_m_per_s;
  const double M = m.wheel.mass_kg;
  const std::vector<MomentumJump> jumps = rigid_impacts(m, run.vertical_external_force_N, trajectory);
  KinematicOutcome& outcome = result.outcome.emplace<KinematicOutcome>();
  // The impact at the joint is the jump nearest the predicted one; jumps
  // before it mean the wheel left the kinematic path (self-check).
  std::vector<double> earlier_jumps_Ns;
  if (!jumps.empty()) {
    std::size_t k = 0;
    for (std::size_t j = 1; j < jumps.size(); ++j) {
      if (std::abs(jumps[j].wheel_x_m - m.prediction.impact_wheel_x_m) <
          std::abs(jumps[k].wheel_x_m - m.prediction.impact_wheel_x_m)) {
        k = j;
      }
    }
    for (std::size_t j = 0; j < k; ++j) earlier_jumps_Ns.push_back(jumps[j].jump_Ns);
    const MomentumJump& impact = jumps[k];
    result.impact = impact;
    const double liftoff_time_s = find_liftoff_time_s(trajectory, impact.last_sample);
    if (liftoff_time_s >= 0) outcome.liftoff_time_s = liftoff_time_s;
    if (k + 1 < jumps.size()) result.second_impact = FollowingImpact{jumps[k + 1].time_s, jumps[k + 1].jump_Ns};
  }
  result.verdict = kinematic_self_check(
      result, m.settings, v, M, kinematic_centre_slope(m.joint, m.simulated_wheel, m.prediction.impact_wheel_x_m, -1),
      earlier_jumps_Ns);
  return result;
}

SimulationResult analyse_inertial_crossing(std::shared_ptr<const CrossingModel> model, CrossingRun run) {
  const CrossingModel& m = *model;
  SimulationResult result = result_of(std::move(model), run);
  Trajectory& trajectory = result.trajectory;
  const ImpactPrediction& p = m.prediction;
  const SimSettings& settings = m.settings;
  const double v = m.wheel.speed_m_per_s;
  const double M = m.wheel.mass_kg;
  const double R = m.wheel.radius_m;
  const double flat = m.flat_approach_m();
  InertialOutcome& out = result.outcome.emplace<InertialOutcome>();
  const InertialSettings& inertial = *settings.inertial();
  out.static_load_N = inertial.wheel_load_N + M * kStandardGravity_m_per_s2;
  const double W = out.static_load_N;
  if (m.compliant()) {
    CompliantContact& c = out.compliant.emplace();
    // A force run's Hertz contact as the spring it is at the static load; it has no damper of its own.
    const LinearContactSettings* spring = inertial.linear_contact();
    c.stiffness_N_per_m =
        spring ? spring->stiffness_N_per_m : linearised_hertz_stiffness_N_per_m(m.hertz_constant_m_per_N2_3, W);
    c.damping_N_s_per_m = spring ? spring->damping_N_s_per_m : 0.0;
  }

  // Phases against the kinematic reference path.
  PhaseDetection phase_detection;
  // A thousandth of the static load: a pivot near its lift-off speed still
  // carries a few % of it, solver noise on a lost contact is far below.
  phase_detection.min_contact_force_N = std::max(1.0, 1e-3 * W);
  // A solved rigid contact lets the wheel drift between the slop and the
  // processing threshold (1 um by default) without leaving the rail: a
  // flight must rise twice that band above the kinematic path.
  phase_detection.min_flight_clearance_m =
      std::max(5e-7, 2.0 * (m.settings.slop_m + m.settings.contact_processing_threshold_m));
  const ContactPhaseAnalysis phases = analyse_contact_phases(
      trajectory, [&m](double x) { return m.reference_height_m(x); }, phase_detection);
  static_cast<ContactPhaseSummary&>(out) = phases;  // all but the force history, which the force outcome keeps
  if (m.elastic()) out.forces = force_outcome(m, run, trajectory, phases.vertical_force_N, W);

  // Impacts: velocity jumps (rigid) or force pulses (compliant).
  std::vector<MomentumJump> jumps;
  if (out.compliant) {
    trajectory.impacts = force_pulses(trajectory, phases.vertical_force_N, W);
  } else {
    jumps = rigid_impacts(m, run.vertical_external_force_N, trajectory);
  }
  for (ImpactEvent& event : trajectory.impacts) {
    out.total_impulse_Ns += event.momentum_jump_Ns;
    for (const Flight& f : out.flights) {
      // The flight's landing sample opens the impact (rigid), or lies in the pulse (compliant).
      if (f.landed && f.last_sample + 1 + 2 >= event.first_sample && f.last_sample + 1 <= event.last_sample + 2) {
        event.landing = true;
      }
    }
  }
  for (std::size_t i = 0; i < trajectory.impacts.size(); ++i) {
    const ImpactEvent& e = trajectory.impacts[i];
    if (std::abs(e.wheel_x_m - p.impact_wheel_x_m) > kJointImpactWindow_m) continue;
    if (out.joint_impact_index < 0 ||
        e.momentum_jump_Ns > trajectory.impacts[static_cast<std::size_t>(out.joint_impact_index)].momentum_jump_Ns) {
      out.joint_impact_index = static_cast<int>(i);
    }
  }
  for (std::size_t i = 0; i < trajectory.impacts.size() && out.joint_impact_index < 0; ++i) {
    if (trajectory.impacts[i].wheel_x_m >= p.impact_wheel_x_m - kJointImpactWindow_m) {
      out.joint_impact_index = static_cast<int>(i);
    }
  }

  if (out.joint_impact_index >= 0) {
    const std::size_t j = static_cast<std::size_t>(out.joint_impact_index);
    const ImpactEvent& e = trajectory.impacts[j];
    out.joint_horizontal_impulse_Ns = e.horizontal_impulse_Ns;
    if (!jumps.empty()) {
      result.impact = jumps[j];
    } else {
      // A force pulse, with the velocities at its ends.
      const Eigen::Vector3d& before = trajectory.samples[e.first_sample - 1].velocity_m_per_s;
      const Eigen::Vector3d& after = trajectory.samples[e.last_sample].velocity_m_per_s;
      result.impact = CompliantPulse{e, before.z(), after.z(), before.x(), after.x()};
    }
    if (j + 1 < trajectory.impacts.size()) {
      result.second_impact =
          FollowingImpact{trajectory.impacts[j + 1].time_s, trajectory.impacts[j + 1].momentum_jump_Ns};
    }
  }

  // The lift-off model: the corner the kinematic wheel pivots about at the
  // joint (A), the angle of its radius at the two-point contact, and the
  // speed above which the static load cannot hold the wheel on that arc.
  if (p.scenario != ImpactScenario::one) {
    out.pivot_angle_rad = p.alpha_rad;
    out.pivot_liftoff_speed_m_per_s = pivot_liftoff_speed_m_per_s(M, R, W, out.pivot_angle_rad);
    out.liftoff_predicted = v > out.pivot_liftoff_speed_m_per_s;
  }
  if (flat > 0.0 && m.joint.kind == JointKind::inclined) {
    out.entry_kink_liftoff_speed_m_per_s = pivot_liftoff_speed_m_per_s(M, R, W, m.joint.beta_rad / 2.0);
    out.liftoff_predicted = out.liftoff_predicted || v > out.entry_kink_liftoff_speed_m_per_s;
  }

  // A compliant wheel sinks below the path by its contact's (and the track's) compression.
  double tolerance_m = 2e-5 + (out.compliant ? out.peak_force_N / out.compliant->stiffness_N_per_m : 0.0);
  if (m.elastic()) {
    tolerance_m = 2e-5 + hertz_approach_m(m.hertz_constant_m_per_N2_3, out.peak_force_N);
    // And the track by P / K_T (the lumped track's K_T: pad and ballast in series).
    if (const std::optional<JenkinsTrack>& t = out.forces->jenkins.track) {
      tolerance_m += out.peak_force_N / t->track_stiffness_N_per_m;
    }
  }
  out.followed_kinematic_path = out.flights.empty() && out.max_deviation_m <= tolerance_m;
  if (out.compliant) {
    CompliantContact& c = *out.compliant;
    c.rigid_track_p1_N = rigid_track_peak_force_N(W, p.impulse.exact_Ns / M, c.stiffness_N_per_m, M);
    c.rigid_track_p1_beta_v_N =
        jenkins_p1_force_N(W, m.joint.beta_rad, v, c.stiffness_N_per_m, M, std::numeric_limits<double>::infinity());
  }

  result.verdict = inertial_self_check(result, m.settings);
  return result;
}

}  // namespace railjoint
