#include "sim/inertial_crossing.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <string>

#include "geometry/rail_joint_mesh.h"
#include "models/rail_top.h"
#include "models/kinematic_trajectory.h"
#include "models/liftoff.h"
#include "models/input_error.h"
#include "models/slice_profile.h"
#include "sim/contact_phases.h"
#include "sim/closing_gap_step.h"
#include "sim/event_located_step.h"
#include "sim/crossing_world.h"
#include "sim/impact_force_estimate.h"
#include "sim/momentum_jump.h"
#include "sim/setting_checks.h"

namespace railjoint {

namespace {

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

}  // namespace

double inertial_reference_height_m(const JointParams& joint, const WheelParams& wheel, double flat_approach_m,
                                   double wheel_x_m) {
  double z = kinematic_centre_height_m(joint, wheel, wheel_x_m);
  if (flat_approach_m > 0.0) {
    const double x_kink = -0.5 * joint.length_m;
    const double h = flat_approach_height_m(joint);
    const ProfileSegment flat{{x_kink - flat_approach_m, h}, {x_kink, h}};
    z = std::max(z, segment_support(flat, wheel.radius_m, wheel_x_m).centre_z_m);
  }
  return z;
}

void check_inertial_settings(const SimSettings& settings, const JointParams& /*joint*/, const WheelParams& wheel) {
  require_setting(!settings.preload_N.has_value(), "preload",
          "is the kinematic mode's glue; in inertial mode the wheel is loaded by sim.wheel_load (and its weight)");
  require_setting(settings.wheel_load_N >= 0 && std::isfinite(settings.wheel_load_N), "wheel_load", "must be >= 0 N");
  require_setting(!settings.carrier_mass_kg || (*settings.carrier_mass_kg >= 0 && std::isfinite(*settings.carrier_mass_kg)),
          "carrier_mass", "must be >= 0 kg");
  require_setting(!settings.radius_of_gyration_m ||
              (*settings.radius_of_gyration_m > 0 && *settings.radius_of_gyration_m <= wheel.radius_m),
          "radius_of_gyration", "must be in (0, R] = (0, " + setting_number(wheel.radius_m) + "] m");
  require_setting(settings.flat_approach_m >= 0 && std::isfinite(settings.flat_approach_m), "flat_approach", "must be >= 0 m");
  // The wheel starts half way along the flat with its contact point on it.
  require_setting(settings.flat_approach_m == 0.0 || settings.flat_approach_m >= 0.02, "flat_approach",
          "must be 0 (start on the slope) or >= 0.02 m (the wheel starts half way along it)");
  if (settings.contact_stiffness_N_per_m) {
    const double k = *settings.contact_stiffness_N_per_m;
    require_setting(k > 0 && std::isfinite(k), "contact_stiffness", "must be > 0 N/m");
    // The contact oscillates at omega = sqrt(k / M); the fine step must
    // resolve it (implicit Euler damps it by ~omega dt per radian).
    const double omega = std::sqrt(k / wheel.mass_kg);
    require_setting(omega * settings.refined_time_step_s <= 0.05, "refined_time_step",
            "must be <= 0.05 / sqrt(k / M) = " + setting_number(0.05 / omega) +
                " s to resolve the contact spring (sim.contact_stiffness = " + setting_number(k) + " N/m)");
  }
  require_setting(settings.contact_damping_N_s_per_m >= 0 && std::isfinite(settings.contact_damping_N_s_per_m),
          "contact_damping", "must be >= 0 N s/m");
}

SimulationResult simulate_inertial_crossing(const JointParams& joint, const WheelParams& wheel,
                                            const SimSettings& settings) {
  SimulationResult result;
  result.simulated_wheel = wheel_as_simulated(wheel, settings);
  const WheelParams& simulated = result.simulated_wheel;
  result.prediction = predict_impact(joint, simulated);
  if (wheel.width_m == 0.0) result.thin_disc_prediction = predict_impact(joint, wheel);
  const ImpactPrediction& p = result.prediction;

  const double v = wheel.speed_m_per_s;
  const double M = wheel.mass_kg;
  const double R = wheel.radius_m;
  result.preload_N = settings.wheel_load_N;
  InertialOutcome& out = result.inertial.emplace();
  out.wheel_load_N = settings.wheel_load_N;
  out.static_load_N = settings.wheel_load_N + M * kStandardGravity_m_per_s2;
  out.horizontal = settings.horizontal;
  out.carrier_mass_kg = settings.horizontal == HorizontalMotion::free ? resolved_carrier_mass_kg(settings) : 0.0;
  out.spinning = settings.friction > 0.0;
  out.flat_approach_m = settings.flat_approach_m;
  out.compliant = settings.contact_stiffness_N_per_m.has_value();
  out.contact_stiffness_N_per_m = settings.contact_stiffness_N_per_m.value_or(0.0);
  out.contact_damping_N_s_per_m = out.compliant ? settings.contact_damping_N_s_per_m : 0.0;
  const double W = out.static_load_N;
  const double flat = settings.flat_approach_m;

  const auto start_clock = std::chrono::steady_clock::now();

  // Start: on the flat half way along it, or on the incoming slope
  // approach_distance before the predicted impact, with the matching
  // vertical velocity. A compliant contact starts compressed by its static
  // load: the spring along the normal (tilted by gamma) carries W / cos(gamma),
  // which sinks the centre by W / (k cos^2 gamma).
  WheelStart start;
  double slope = 0.0;
  if (flat > 0.0) {
    const double x0 = -0.5 * joint.length_m - 0.5 * flat;
    start.centre_m = Eigen::Vector3d(x0, simulated.lateral_m, flat_approach_height_m(joint) + R);
  } else {
    const double x0 = p.impact_wheel_x_m - settings.approach_distance_m;
    start.centre_m = Eigen::Vector3d(x0, simulated.lateral_m, kinematic_centre_height_m(joint, simulated, x0));
    slope = kinematic_centre_slope(joint, simulated, x0, +1);
  }
  start.vertical_velocity_m_per_s = v * slope;
  if (out.compliant) {
    const double cos2 = 1.0 / (1.0 + slope * slope);
    start.centre_m.z() -= W / (out.contact_stiffness_N_per_m * cos2);
  }
  const double x0 = start.centre_m.x();

  RailJointMeshOptions mesh_options;
  mesh_options.flat_approach_m = flat;
  const RailJointMesh mesh = build_rail_joint_mesh(joint, mesh_options);
  CrossingWorld world({mesh.incoming, mesh.outgoing}, simulated, settings, settings.wheel_load_N, start);

  const double end_time_s = (p.impact_wheel_x_m - x0) / v + settings.run_out_time_s;
  Trajectory& trajectory = result.trajectory;
  trajectory.samples.reserve(static_cast<std::size_t>(end_time_s / settings.time_step_s) + 4000);
  trajectory.samples.push_back(world.sample());

  // Step size as in kinematic mode (simulate_crossing.cpp): coarse while no
  // gap is about to close, cut to a quarter of the closing time as one
  // closes, fine below refine_distance and for refine_hold after a strike, a
  // turn about a contact, or near the end of the incoming rail or the entry
  // kink of a flat approach.
  double refine_until_s = -1.0;
  double min_distance_m = 0.0;
  const double kink_x_m = -0.5 * joint.length_m;
  // In flight zdot changes by g_eff dt every step: that is no strike (with a
  // 1e-4 s step it exceeds the kinematic mode's 1e-4 v threshold).
  const double flight_acceleration_m_per_s2 = std::abs(world.vertical_external_force_N()) / M;
  double next_dt = settings.time_step_s;
  // Impacts and landings located as in kinematic mode (event_located_step.h).
  const EventLocation location = impact_location(settings, v, world.compliant());
  std::vector<ContactSample> contacts_now = world.probe_contacts();
  while (world.time_s() < end_time_s - 1e-12) {
    double dt =
        std::min(world.time_s() < refine_until_s ? settings.refined_time_step_s : next_dt, end_time_s - world.time_s());
    LocatedStep step = step_locating_impacts(world, dt, contacts_now, location);
    dt = step.dt_s;
    contacts_now = std::move(step.contacts_now);
    ++result.steps;
    if (dt <= settings.refined_time_step_s * (1 + 1e-9)) ++result.refined_steps;
    WheelSample sample = std::move(step.sample);
    const double dzdot = std::abs(sample.velocity_m_per_s.z() - trajectory.samples.back().velocity_m_per_s.z());
    const auto solved = [&](const ContactSample& c) { return c.distance_m <= settings.contact_processing_threshold_m; };
    const bool in_contact = std::any_of(sample.contacts.begin(), sample.contacts.end(), solved);
    const bool near_edge = std::any_of(sample.contacts.begin(), sample.contacts.end(), [&](const ContactSample& c) {
      if (c.rail_index != 0 || !solved(c)) return false;
      const double reach = 2.0 * v * settings.time_step_s;
      const double to_cut = cut_x_m(joint, c.point_on_rail_m.y(), 0) - c.point_on_rail_m.x();
      const double to_kink = kink_x_m - c.point_on_rail_m.x();
      return to_cut < reach || (flat > 0.0 && to_kink > -reach && to_kink < reach);
    });
    if (dzdot > 1e-4 * v + 2.0 * flight_acceleration_m_per_s2 * dt || (in_contact && dzdot > 1e-5 * v) || near_edge) {
      refine_until_s = world.time_s() + refine_hold_in_use_s(settings);
    }
    for (const ContactSample& c : sample.contacts) min_distance_m = std::min(min_distance_m, c.distance_m);
    const ClosingGapStep gap_step = closing_gap_step(sample.contacts, settings, v, dt);
    if (gap_step.refine) refine_until_s = world.time_s() + refine_hold_in_use_s(settings);
    next_dt = gap_step.next_dt_s;
    trajectory.samples.push_back(std::move(sample));
  }
  result.max_penetration_m = -min_distance_m;

  // Phases against the kinematic reference path.
  PhaseDetection phase_detection;
  // A thousandth of the static load: a pivot near its lift-off speed still
  // carries a few % of it, solver noise on a lost contact is far below.
  phase_detection.min_contact_force_N = std::max(1.0, 1e-3 * W);
  // A solved rigid contact lets the wheel drift between the slop and the
  // processing threshold (1 um by default) without leaving the rail: a
  // flight must rise twice that band above the kinematic path.
  phase_detection.min_flight_clearance_m =
      std::max(5e-7, 2.0 * (settings.slop_m + settings.contact_processing_threshold_m));
  const ContactPhaseAnalysis phases = analyse_contact_phases(
      trajectory, [&](double x) { return inertial_reference_height_m(joint, simulated, flat, x); }, phase_detection);
  out.phases = phases.phases;
  out.flights = phases.flights;
  out.ended_in_flight = phases.ended_in_flight;
  out.max_deviation_m = phases.max_deviation_m;
  out.max_deviation_x_m = phases.max_deviation_x_m;
  out.max_rise_m = phases.max_rise_m;
  out.max_sink_m = phases.max_sink_m;
  out.peak_force_N = phases.peak_force_N;
  out.peak_force_time_s = phases.peak_force_time_s;
  out.peak_force_x_m = phases.peak_force_x_m;

  // Impacts: velocity jumps (rigid) or force pulses (compliant).
  std::vector<MomentumJump> jumps;
  if (out.compliant) {
    trajectory.impacts = force_pulses(trajectory, phases.vertical_force_N, W);
  } else {
    const JumpDetection detection =
        jump_detection_for(M, v, R, world.vertical_external_force_N(), -settings.slop_m);
    jumps = find_momentum_jumps(trajectory, detection);
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
    result.impact_found = true;
    result.impulse_Ns = e.momentum_jump_Ns;
    result.impact_time_s = e.time_s;
    result.impact_x_m = e.wheel_x_m;
    result.contact_struck_m = e.contact_point_m;
    out.joint_horizontal_impulse_Ns = e.horizontal_impulse_Ns;
    if (!jumps.empty()) {
      const MomentumJump& jump = jumps[j];
      result.impulse_from_contacts_Ns = jump.from_contacts_Ns;
      result.zdot_before_m_per_s = jump.zdot_before_m_per_s;
      result.zdot_after_m_per_s = jump.zdot_after_m_per_s;
      result.contact_left_m = jump.left_point_m;
      out.xdot_before_m_per_s = jump.xdot_before_m_per_s;
      out.xdot_after_m_per_s = jump.xdot_after_m_per_s;
    } else {
      // A force pulse: velocities at its ends.
      const WheelSample& a = trajectory.samples[e.first_sample - 1];
      const WheelSample& b = trajectory.samples[e.last_sample];
      result.impulse_from_contacts_Ns = e.momentum_jump_Ns;
      result.zdot_before_m_per_s = a.velocity_m_per_s.z();
      result.zdot_after_m_per_s = b.velocity_m_per_s.z();
      out.xdot_before_m_per_s = a.velocity_m_per_s.x();
      out.xdot_after_m_per_s = b.velocity_m_per_s.x();
    }
    if (j + 1 < trajectory.impacts.size()) {
      result.second_impact = true;
      result.second_impact_time_s = trajectory.impacts[j + 1].time_s;
      result.second_impulse_Ns = trajectory.impacts[j + 1].momentum_jump_Ns;
    }
  }
  if (!out.flights.empty()) {
    result.liftoff = true;
    result.liftoff_time_s = out.flights.front().liftoff_time_s;
  }

  // The lift-off model: the corner the kinematic wheel pivots about at the
  // joint (A), the angle of its radius at the two-point contact, and the
  // speed above which the static load cannot hold the wheel on that arc.
  if (p.scenario != ImpactScenario::one) {
    const double lead = std::abs(p.impact_wheel_x_m - p.contact_A_m.x());
    out.pivot_angle_rad = std::asin(std::min(1.0, lead / R));
    out.pivot_liftoff_speed_m_per_s = pivot_liftoff_speed_m_per_s(M, R, W, out.pivot_angle_rad);
    out.liftoff_predicted = v > out.pivot_liftoff_speed_m_per_s;
  }
  if (flat > 0.0 && joint.kind == JointKind::inclined) {
    out.entry_kink_liftoff_speed_m_per_s = pivot_liftoff_speed_m_per_s(M, R, W, joint.beta_rad / 2.0);
    out.liftoff_predicted = out.liftoff_predicted || v > out.entry_kink_liftoff_speed_m_per_s;
  }

  const double tolerance_m = 2e-5 + (out.compliant ? out.peak_force_N / out.contact_stiffness_N_per_m : 0.0);
  out.followed_kinematic_path = out.flights.empty() && out.max_deviation_m <= tolerance_m;
  if (out.compliant) {
    out.rigid_track_p1_N = rigid_track_peak_force_N(W, p.impulse.exact_Ns / M, out.contact_stiffness_N_per_m, M);
    out.rigid_track_p1_beta_v_N = jenkins_p1_force_N(W, joint.beta_rad, v, out.contact_stiffness_N_per_m, M,
                                                     std::numeric_limits<double>::infinity());
  }

  result.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_clock).count();
  return result;
}

}  // namespace railjoint
