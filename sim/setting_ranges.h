#pragma once
// The range of each [sim] setting and the table that ties each key to its
// range, its field and the runs that read it, written once: the scene reader
// reads a mode's keys and refuses the other's by it (scenes/sim_section.cpp),
// a force run refuses the keys it does not read (scenes/force_sections.cpp),
// and check_sim_settings refuses a value built in code outside its range
// (setting_checks.h); the [contact], [track] and [vehicle] keys' are
// force_setting_ranges.h's. Limits that depend on the joint or the wheel
// (slop < 0.01 R, a margin inside the wheel's half width, a run that starts
// and ends on the rails) are setting_checks' alone. Plain header: no Bullet.

#include <cmath>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "sim/sim_settings.h"

namespace railjoint {

struct SettingRange {
  double lo = 0.0;
  double hi = 0.0;
  bool lo_open = false;
  bool hi_open = false;
  const char* unit = "";

  bool contains(double x) const {
    if (std::isnan(x)) return false;
    return (lo_open ? x > lo : x >= lo) && (hi_open ? x < hi : x <= hi);
  }
};

namespace sim_range {

// Steps: 1e-7 s coarse (the convergence study's finest fixed step is 1e-6 s)
// and 1e-9 s fine (50 nm of travel at 50 m/s; the error stops falling at
// 3e-7 s, docs/convergence.md, "Error against run time"). Smaller ones only cost: below
// t * 1.1e-16 a step no longer advances the clock at all
// (docs/reliability.md, "Run length"). The whole run is bounded too
// (check_sim_run_length).
inline constexpr SettingRange time_step{1e-7, 1e-2, false, false, "s"};
inline constexpr SettingRange refined_time_step{1e-9, 1e-2, false, false, "s"};
inline constexpr SettingRange refine_distance{0.0, 0.1, false, false, "m"};
inline constexpr SettingRange refine_hold{0.0, 1.0, false, false, "s"};
// 1 nm: a thousandth of the default margin, still ~1e7 units of round-off of
// a coordinate near 1 m.
inline constexpr SettingRange margin{1e-9, 0.04, false, true, "m"};
inline constexpr SettingRange contact_breaking_threshold{1e-9, 0.1, false, false, "m"};
inline constexpr SettingRange contact_processing_threshold{-1e-3, 0.1, false, false, "m"};
inline constexpr SettingRange split_impulse_threshold{-0.1, 0.0, false, false, "m"};
inline constexpr SettingRange slop{0.0, 1e-3, false, false, "m"};
inline constexpr SettingRange solver_iterations{1.0, 1000.0, false, false, ""};
// Upper bounds well past anything physical (the stability study goes to a
// 1e8 N preload), so a typo in an exponent is caught rather than run.
inline constexpr SettingRange preload{0.0, 1e9, false, false, "N"};
inline constexpr SettingRange friction{0.0, 2.0, false, false, ""};
inline constexpr SettingRange restitution{0.0, 1.0, false, false, ""};
inline constexpr SettingRange disc_half_width{0.0, 0.02, true, false, "m"};
inline constexpr SettingRange approach_distance{0.0, 100.0, true, false, "m"};
inline constexpr SettingRange run_out_time{0.0, 10.0, true, false, "s"};
inline constexpr SettingRange wheel_load{0.0, 1e7, false, false, "N"};
inline constexpr SettingRange carrier_mass{0.0, 1e7, false, false, "kg"};
inline constexpr SettingRange radius_of_gyration{0.0, 10.0, true, false, "m"};
inline constexpr SettingRange flat_approach{0.0, 100.0, false, false, "m"};
// 1e-8 s: 0.8 um of travel at 80 m/s; 1e-4 s: a few steps across a P1 pulse.
inline constexpr SettingRange force_time_step{1e-8, 1e-4, false, false, "s"};

}  // namespace sim_range

/// The runs that read a [sim] key, a bit each: the kinematic run, the
/// inertial runs Bullet steps (a rigid or a linear contact) and the force run
/// (contact.law = "hertz"). A mode's reader reads the keys of its runs
/// (kinematic: kKinematicRun; inertial: kInertialRuns, before it knows the
/// contact law) and refuses the others.
inline constexpr unsigned kKinematicRun = 1, kBulletInertialRun = 2, kForceRun = 4;
inline constexpr unsigned kBulletRuns = kKinematicRun | kBulletInertialRun;
inline constexpr unsigned kInertialRuns = kBulletInertialRun | kForceRun;
inline constexpr unsigned kEveryRun = kBulletRuns | kForceRun;

/// What a [sim] key sets, which says why a run that does not read it
/// refuses it (scenes/force_sections.cpp).
enum class SimKeyPart {
  run,            ///< the mode, the wheel's load, the run's span and step
  bullet,         ///< Bullet's steps, contact detection and solver
  rigid_contact,  ///< the rigid contact's dissipation and horizontal motion
  flat_approach,  ///< the level rail before the dip
};

/// The setting a [sim] key fills: a number with a default or one that may
/// be left out, a count, a switch or a choice; nothing for the mode (read
/// first, it picks the runs) and for a key of the mode the settings are not in.
using SimKeyField =
    std::variant<std::monostate, double*, std::optional<double>*, int*, bool*, NarrowPhase*, HorizontalMotion*>;

/// One [sim] key, in the order the reader reads them: the runs that read
/// it, its range (a number's) and its field.
struct SimSettingKey {
  const char* key;  ///< within [sim]: "time_step"
  unsigned runs;
  SimKeyPart part;
  SettingRange range;
  SimKeyField field;
};

/// [sim]'s keys, filling `sim` and the part of its mode (sim.kinematic() or sim.inertial()).
inline std::vector<SimSettingKey> sim_keys(SimSettings& sim) {
  using Part = SimKeyPart;
  // A mode's field, where the settings are in that mode.
  const auto of_mode = [](auto* mode, auto member) -> SimKeyField {
    if (mode == nullptr) return {};
    return &(mode->*member);
  };
  InertialSettings* const inertial = sim.inertial();
  return {{"mode", kEveryRun, Part::run, {}, {}},
          {"time_step", kBulletRuns, Part::bullet, sim_range::time_step, &sim.time_step_s},
          // A force run steps its impact's pulse at the default (1e-6 s) but
          // does not take the key: its step is sim.force_time_step, which
          // set below 1e-6 s steps everything finer (docs/forces.md).
          {"refined_time_step", kBulletRuns, Part::bullet, sim_range::refined_time_step, &sim.refined_time_step_s},
          {"refine_distance", kBulletRuns, Part::bullet, sim_range::refine_distance, &sim.refine_distance_m},
          {"refine_hold", kBulletRuns, Part::bullet, sim_range::refine_hold, &sim.refine_hold_s},
          {"margin", kBulletRuns, Part::bullet, sim_range::margin, &sim.margin_m},
          // A force run's contact is seen within it too (its reach).
          {"contact_breaking_threshold", kEveryRun, Part::bullet, sim_range::contact_breaking_threshold,
           &sim.contact_breaking_threshold_m},
          {"contact_processing_threshold", kBulletRuns, Part::bullet, sim_range::contact_processing_threshold,
           &sim.contact_processing_threshold_m},
          {"split_impulse_threshold", kBulletRuns, Part::bullet, sim_range::split_impulse_threshold,
           &sim.split_impulse_threshold_m},
          {"slop", kBulletRuns, Part::bullet, sim_range::slop, &sim.slop_m},
          {"solver_iterations", kBulletRuns, Part::bullet, sim_range::solver_iterations, &sim.solver_iterations},
          {"hard_contacts", kBulletRuns, Part::bullet, {}, &sim.hard_contacts},
          {"narrow_phase", kBulletRuns, Part::bullet, {}, &sim.narrow_phase},
          {"preload", kKinematicRun, Part::run, sim_range::preload,
           of_mode(sim.kinematic(), &KinematicSettings::preload_N)},
          {"friction", kBulletRuns, Part::rigid_contact, sim_range::friction, &sim.friction},
          {"restitution", kBulletRuns, Part::rigid_contact, sim_range::restitution, &sim.restitution},
          {"internal_edge_fix", kBulletRuns, Part::bullet, {}, &sim.internal_edge_fix},
          {"disc_half_width", kEveryRun, Part::run, sim_range::disc_half_width, &sim.disc_half_width_m},
          {"approach_distance", kEveryRun, Part::run, sim_range::approach_distance, &sim.approach_distance_m},
          {"run_out_time", kEveryRun, Part::run, sim_range::run_out_time, &sim.run_out_time_s},
          {"wheel_load", kInertialRuns, Part::run, sim_range::wheel_load,
           of_mode(inertial, &InertialSettings::wheel_load_N)},
          {"horizontal", kBulletInertialRun, Part::rigid_contact, {}, of_mode(inertial, &InertialSettings::horizontal)},
          {"carrier_mass", kBulletInertialRun, Part::rigid_contact, sim_range::carrier_mass,
           of_mode(inertial, &InertialSettings::carrier_mass_kg)},
          {"radius_of_gyration", kBulletInertialRun, Part::rigid_contact, sim_range::radius_of_gyration,
           of_mode(inertial, &InertialSettings::radius_of_gyration_m)},
          {"flat_approach", kBulletInertialRun, Part::flat_approach, sim_range::flat_approach,
           of_mode(inertial, &InertialSettings::flat_approach_m)},
          {"force_time_step", kForceRun, Part::run, sim_range::force_time_step,
           of_mode(inertial, &InertialSettings::force_time_step_s)}};
}

}  // namespace railjoint
