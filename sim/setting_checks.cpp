#include "sim/setting_checks.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "geometry/rail_joint_mesh.h"
#include "models/parameter_checks.h"
#include "models/rail_head.h"
#include "sim/discrete_track.h"
#include "sim/rail_surface.h"

namespace railjoint {

namespace {

void check_simulated_wheel_on_head(const SimSettings& settings, const JointParams& joint, const WheelParams& wheel) {
  if (wheel.width_m > 0.0) return;
  // Measured with the default settings (scenario 2, theta 30 deg): a thin
  // disc's stand-in cylinder with a rim on the head's side edge or over it on
  // the step-down side gives jumps off by +1.5 % (y = 19.5 mm) and -58 %
  // (y = -19.5 mm, a contact at the start); one cylinder width inside the
  // edge (19 mm) both sides agree within 0.03 %. A finite-width wheel with its
  // rim on the edge (4 mm at |y| = 18 mm) stays within 0.07 %.
  const double y_max_m = joint.half_width_m - 2.0 * settings.disc_half_width_m;
  // 1e-12 m of slack: y_max is a difference of two user numbers (0.03 - 0.001
  // is not 0.029 in binary), and the user's 0.029 must pass.
  if (!(std::abs(wheel.lateral_m) <= y_max_m + 1e-12)) {
    throw InputError("wheel.y", "for the simulation a thin disc (a cylinder 2 sim.disc_half_width = " +
                                        setting_number(2.0 * settings.disc_half_width_m) +
                                        " m wide) must keep its width clear of the rail-head edge: |y| <= "
                                        "joint.half_width - 2 sim.disc_half_width = " +
                                        setting_number(y_max_m) + " m, got " + setting_number(wheel.lateral_m) +
                                        " m (the analytic command takes any |y| <= joint.half_width)");
  }
}

// The joint and wheel keys that make a run need the analytic rail tops
// (has_thesis_geometry), the one the user typed last first.
std::vector<std::string> analytic_top_keys(const JointParams& joint, const WheelParams& wheel,
                                           const KeyOrigins& origins) {
  std::vector<std::string> keys;
  if (!has_flat_head(joint)) keys.insert(keys.end(), {"joint.rail_profile", "joint.crown_radius"});
  if (wheel.measured_tread || wheel.conicity != 0.0) keys.insert(keys.end(), {"wheel.profile", "wheel.conicity"});
  if (joint.dip_shape != DipShape::linear) keys.push_back("joint.dip_shape");
  std::stable_sort(keys.begin(), keys.end(),
                   [&](const std::string& a, const std::string& b) { return origins(a) > origins(b); });
  return keys;
}

// The analytic tops (sim/rail_surface.h) are the rails of the model, from
// -L/2 to +L/2: no flat approach on them, and Bullet's own narrow phase sees
// only the meshes. Every mode steps on them through the exact narrow phase
// (sim/exact_wheel_rail_algorithm.h): the kinematic and the rigid inertial
// runs as Bullet contacts, the linear contact as Bullet's spring on that one
// point, the force runs through force_contact_geometry.h. The [sim] key is
// blamed unless the user typed the geometry after it (--set on a file that
// makes an inertial or Bullet run).
void check_analytic_tops_settings(const SimSettings& settings, const JointParams& joint, const WheelParams& wheel,
                                  const KeyOrigins& origins) {
  const std::vector<std::string> geometry_keys = analytic_top_keys(joint, wheel, origins);
  const auto refuse = [&](const std::string& sim_key, const std::string& value, const std::string& needed,
                          const std::string& why) {
    const std::string& geometry_key = geometry_keys.front();
    if (origins(geometry_key) > origins(sim_key)) {
      throw InputError(geometry_key, "cannot be simulated with " + sim_key + " = " + value + " (" +
                                         origin_text(origins(sim_key)) + "): " + why + "; leave " + geometry_key +
                                         " as the file has it, or simulate a scene with " + sim_key + " = " + needed);
    }
    throw InputError(sim_key, "must be " + needed + " for a crowned head, a conical tread or a curved dip: " + why);
  };
  if (settings.inertial() && settings.inertial()->flat_approach_m > 0.0) {
    refuse("sim.flat_approach", setting_number(settings.inertial()->flat_approach_m), "0",
           "the analytic tops are the model's rails from -L/2 to L/2, with no level approach before them");
  }
  if (settings.narrow_phase != NarrowPhase::exact) {
    refuse("sim.narrow_phase", "\"bullet\"", "\"exact\"", "Bullet's narrow phase sees only the meshed rails");
  }
}

// Each [sim] key's own range, as the scene reader takes it (setting_ranges.h),
// for settings built in code: the keys a kinematic run reads (both modes
// have them, the kinematic mode its preload too), or the inertial mode's own.
void check_sim_key_ranges(const SimSettings& settings, bool kinematic_run_keys) {
  SimSettings fields = settings;  // the table holds pointers to fill
  for (const SimSettingKey& k : sim_keys(fields)) {
    if (((k.runs & kKinematicRun) != 0) != kinematic_run_keys) continue;
    if (double* const* number = std::get_if<double*>(&k.field)) {
      require_in_range(**number, k.key, k.range);
    } else if (std::optional<double>* const* optional = std::get_if<std::optional<double>*>(&k.field)) {
      if (**optional) require_in_range(***optional, k.key, k.range);
    } else if (int* const* count = std::get_if<int*>(&k.field)) {
      require_in_range(**count, k.key, k.range);
    }
  }
}

// The keys of `table` that `model` takes, each in its range, named as a
// scene writes it ("track.pad_stiffness").
void check_table_ranges(const std::vector<ForceSettingKey>& table, unsigned model, const std::string& section) {
  for (const ForceSettingKey& k : table) {
    if ((k.models & model) == 0) continue;
    const std::optional<double> value = std::visit([](auto* field) -> std::optional<double> { return *field; }, k.field);
    if (value) require_key_in_range(*value, section + "." + k.key, k.range);
  }
}

// Each [contact], [track] and [vehicle] key's own range, as the scene
// reader takes it (force_setting_ranges.h), for a force run built in code.
void check_force_model_ranges(const ElasticCrossingSettings& elastic) {
  HertzContactSettings contact = elastic.contact;
  require_key_in_range(contact.youngs_modulus_Pa, "contact.youngs_modulus", contact_range::youngs_modulus);
  require_key_in_range(contact.poisson_ratio, "contact.poisson_ratio", contact_range::poisson_ratio);
  LinearContactSettings linear;
  std::optional<double> linear_damping;
  check_table_ranges(contact_keys(linear, linear_damping, contact), kHertzLaw, "contact");
  LumpedTrackSettings lumped = elastic.track.value_or(LumpedTrackSettings{});
  DiscreteTrackSettings discrete = elastic.discrete_track.value_or(DiscreteTrackSettings{});
  if (elastic.track) check_table_ranges(track_keys(lumped, discrete, lumped.support), kLumpedTrack, "track");
  if (elastic.discrete_track) check_table_ranges(track_keys(lumped, discrete, discrete.support), kDiscreteTrack, "track");
  if (discrete.timoshenko) check_table_ranges(timoshenko_keys(*discrete.timoshenko), kTimoshenkoBeam, "track");
  PrimarySuspensionSettings sprung = elastic.vehicle.value_or(PrimarySuspensionSettings{});
  BogieSettings bogie = elastic.bogie.value_or(BogieSettings{});
  if (elastic.vehicle) check_table_ranges(vehicle_keys(sprung, bogie, false), kSprungVehicle, "vehicle");
  if (elastic.bogie) check_table_ranges(vehicle_keys(sprung, bogie, true), kBogieVehicle, "vehicle");
}

}  // namespace

void check_setting_pairs(const SimSettings& sim, const KeyOrigins& origins) {
  const auto refuse = [&](const std::string& blamed, const std::string& other, const std::string& message_blamed,
                          const std::string& message_other) {
    const bool blame_other = origins("sim." + other) > origins("sim." + blamed);
    throw InputError("sim." + (blame_other ? other : blamed), blame_other ? message_other : message_blamed);
  };
  if (!(sim.refined_time_step_s <= sim.time_step_s)) {
    refuse("refined_time_step", "time_step",
           "must be <= sim.time_step = " + setting_seconds(sim.time_step_s) + " (the fine step refines the coarse one)",
           "must be >= sim.refined_time_step = " + setting_seconds(sim.refined_time_step_s) +
               " (the fine step refines the coarse one)");
  }
  if (!(sim.refine_distance_m < sim.contact_breaking_threshold_m)) {
    refuse("refine_distance", "contact_breaking_threshold",
           "must be < sim.contact_breaking_threshold = " + metres_text(sim.contact_breaking_threshold_m) +
               " (a gap is seen closing only within that threshold)",
           "must be > sim.refine_distance = " + metres_text(sim.refine_distance_m) +
               " (a gap is seen closing only within this threshold)");
  }
  // Resting contacts overlap by the slop: a threshold at or below -slop drops them.
  if (!(sim.contact_processing_threshold_m > -sim.slop_m)) {
    refuse("contact_processing_threshold", "slop",
           "must be > -sim.slop = " + metres_text(-sim.slop_m + 0.0) + " (resting contacts overlap by the slop)",
           "must be > -sim.contact_processing_threshold = " + metres_text(-sim.contact_processing_threshold_m + 0.0) +
               " (resting contacts overlap by the slop)");
  }
}

std::size_t discrete_track_nodes(const DiscreteTrackSettings& track, double run_reach_m) {
  return DiscreteTrack::node_count_for(track, DiscreteTrack::half_length_for_run_m(track, run_reach_m));
}

double discrete_track_longest_step_s(const DiscreteTrackSettings& track) {
  return 1.0 / DiscreteTrack::highest_frequency_rad_per_s(track);
}

double discrete_track_half_length_m(const DiscreteTrackSettings& track, double run_reach_m) {
  return DiscreteTrack::half_length_for_run_m(track, run_reach_m);
}

namespace {

// The discrete track's grid against the force run's step: nodes_per_bay even
// (a sleeper at a bay's middle node, the joint at a bay's end), and the step
// short enough for the finest grid's stiffest mode. A step too long for the
// grid blames track.nodes_per_bay where the user typed it after the step (or
// left the step at its default), naming the finest grid the step holds.
void check_discrete_track_grid(const DiscreteTrackSettings& track, const InertialSettings& inertial,
                               const KeyOrigins& origins) {
  if (track.nodes_per_bay % 2 != 0) {
    throw InputError("track.nodes_per_bay",
                     "must be even (a sleeper on each bay's middle node, the joint on a bay's end), got " +
                         std::to_string(track.nodes_per_bay));
  }
  // The beam's stiffest mode, a node against its neighbours, rings at
  // 4 / h^2 sqrt(EI / mu); the velocity Verlet step (as the semi-implicit
  // Euler step before it) is stable below 2 / omega and keeps that mode's
  // frequency within 5 % below 1 / omega (2 asin(omega dt / 2) / dt).
  // A Timoshenko rail's (timoshenko_rail.h) is bounded by Gershgorin's
  // theorem, which gives Euler's exactly.
  const double omega = DiscreteTrack::highest_frequency_rad_per_s(track);
  const double dt_s = inertial.force_time_step_s;
  if (dt_s * omega <= 1.0) return;
  const std::string h = "h = track.sleeper_spacing / " + std::to_string(track.nodes_per_bay);
  const std::string mode = track.timoshenko ? "its stiffest mode (a Timoshenko rail's: kappa G A, EI, mu, rho I and " +
                                                  h + ") rings at most at omega = "
                                            : "its stiffest bending mode, 4 / h^2 sqrt(EI / mu) with " + h +
                                                  ", rings at omega = ";
  const std::string why = " for the discrete track's rail: " + mode + setting_number(omega) + " rad/s";
  if (origins("track.nodes_per_bay") > origins("sim.force_time_step")) {
    // The finest even grid this step holds (omega grows as nodes^2).
    DiscreteTrackSettings coarser = track;
    while (coarser.nodes_per_bay > static_cast<int>(track_range::nodes_per_bay.lo) &&
           dt_s * DiscreteTrack::highest_frequency_rad_per_s(coarser) > 1.0) {
      coarser.nodes_per_bay -= 2;
    }
    const bool fits = dt_s * DiscreteTrack::highest_frequency_rad_per_s(coarser) <= 1.0;
    throw InputError("track.nodes_per_bay",
                     (fits ? "must be <= " + std::to_string(coarser.nodes_per_bay) + " for "
                           : std::string("cannot be held by ")) +
                         "sim.force_time_step = " + setting_seconds(dt_s) + " (" +
                         origin_text(origins("sim.force_time_step")) + "): the step must be <= 1 / omega = " +
                         setting_number(1.0 / omega) + " s" + why + "; or set sim.force_time_step <= " +
                         setting_number(1.0 / omega) + " s (a finer grid needs a shorter step, as 1 / nodes^2)");
  }
  require_setting(false, "force_time_step", "must be <= 1 / omega = " + setting_number(1.0 / omega) + " s" + why);
}

}  // namespace

void check_inertial_settings(const SimSettings& settings, const JointParams& /*joint*/, const WheelParams& wheel,
                             const KeyOrigins& origins) {
  // A preload cannot be given here: it is the kinematic mode's (KinematicSettings).
  const InertialSettings& inertial = *settings.inertial();
  check_sim_key_ranges(settings, false);
  if (inertial.radius_of_gyration_m) {
    require_setting(*inertial.radius_of_gyration_m <= wheel.radius_m, "radius_of_gyration",
                    "must be in (0, R] = (0, " + setting_number(wheel.radius_m) + "] m");
  }
  // The wheel starts half way along the flat with its contact point on it.
  require_setting(inertial.flat_approach_m == 0.0 || inertial.flat_approach_m >= 0.02, "flat_approach",
                  "must be 0 (start on the slope) or >= 0.02 m (the wheel starts half way along it)");
  if (const LinearContactSettings* spring = inertial.linear_contact()) {
    const double k = spring->stiffness_N_per_m;
    require_key_in_range(k, "contact.stiffness", contact_range::stiffness);
    // The contact oscillates at omega = sqrt(k / M); the fine step must
    // resolve it (implicit Euler damps it by ~omega dt per radian).
    const double omega = std::sqrt(k / wheel.mass_kg);
    require_setting(omega * settings.refined_time_step_s <= 0.05, "refined_time_step",
            "must be <= 0.05 / sqrt(k / M) = " + setting_number(0.05 / omega) +
                " s to resolve the contact spring (contact.stiffness = " + setting_number(k) + " N/m)");
    require_key_in_range(spring->damping_N_s_per_m, "contact.damping", contact_range::damping);
  }
  const ElasticCrossingSettings* elastic = inertial.elastic();
  if (elastic) check_force_model_ranges(*elastic);
  if (elastic && elastic->discrete_track) check_discrete_track_grid(*elastic->discrete_track, inertial, origins);
}

void check_sim_settings(const SimSettings& settings, const JointParams& joint, const WheelParams& wheel,
                        const KeyOrigins& origins) {
  // Each key's own range (setting_ranges.h, which the scene reader reads too), then what ties it to others.
  check_sim_key_ranges(settings, true);
  check_setting_pairs(settings, origins);
  require_setting(settings.slop_m < 0.01 * wheel.radius_m, "slop",
                  "must be in [0, 0.01 R) = [0, " + setting_number(0.01 * wheel.radius_m) + ") m");
  require_setting(settings.disc_half_width_m > 0 && settings.disc_half_width_m <= joint.half_width_m, "disc_half_width",
          "must be in (0, joint.half_width] = (0, " + setting_number(joint.half_width_m) + "] m");
  check_simulated_wheel_on_head(settings, joint, wheel);
  const double half_width = 0.5 * wheel_as_simulated(wheel, settings).width_m;
  // Bullet's cylinder keeps its margin inside the half extents: a margin of
  // the half width or more leaves no core shape.
  const std::string half_width_source =
      wheel.width_m == 0.0 ? "sim.disc_half_width / 2 for a thin disc" : "wheel.width / 4";
  if (!(settings.margin_m > 0 && settings.margin_m < 0.5 * half_width)) {
    // A finite wheel the user made narrower than the margin allows is the width's fault.
    if (wheel.width_m > 0.0 && origins("wheel.width") > origins("sim.margin")) {
      throw InputError("wheel.width", "must be 0 (a thin disc) or > 4 sim.margin = " +
                                          setting_number(4.0 * settings.margin_m) +
                                          " m for the simulation: the cylinder keeps its margin inside its half "
                                          "width (sim.margin = " + setting_number(settings.margin_m) + " m, " +
                                          origin_text(origins("sim.margin")) + ", goes down to " +
                                          setting_number(sim_range::margin.lo) + " m); got " +
                                          setting_number(wheel.width_m) + " m");
    }
    throw InputError("sim.margin", "must be in (0, " + half_width_source + ") = (0, " +
                                       setting_number(0.5 * half_width) +
                                       ") m: the cylinder keeps its margin inside its half width");
  }
  require_setting(settings.approach_distance_m > 0 && settings.approach_distance_m < 0.4 * joint.length_m, "approach_distance",
          "must be in (0, 0.4 joint.length) = (0, " + setting_number(0.4 * joint.length_m) + ") m (start on the incoming rail)");
  // A run-out derived from the predicted flight is checked against the rails
  // once the prediction is made (build_crossing_model).
  if (settings.run_out_time_s) {
    const double run_out_s = *settings.run_out_time_s;
    require_setting(run_out_s > 0 && run_out_s * wheel.speed_m_per_s < 0.4 * joint.length_m, "run_out_time",
                    "must be in (0, 0.4 joint.length / v) = (0, " +
                        setting_number(0.4 * joint.length_m / wheel.speed_m_per_s) + ") s (end on the outgoing rail)");
  }
  if (settings.inertial()) check_inertial_settings(settings, joint, wheel, origins);
  if (needs_analytic_rail_top(joint, wheel)) check_analytic_tops_settings(settings, joint, wheel, origins);
}

WheelParams simulated_wheel_of(const JointParams& joint, const WheelParams& wheel, const SimSettings& settings) {
  return runs_on_analytic_rail_tops(joint, wheel, settings) ? wheel : wheel_as_simulated(wheel, settings);
}

void check_simulation_inputs(const JointParams& joint, const WheelParams& wheel, const SimSettings& settings,
                             const KeyOrigins& origins) {
  // The joint and wheel first: a sim range derived from them (run-out,
  // margin) must not take the blame for a bad joint or wheel key.
  check_joint_geometry(joint, wheel);
  check_joint_has_jump(joint);
  check_sim_settings(settings, joint, wheel, origins);
}

}  // namespace railjoint
