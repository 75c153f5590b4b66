#pragma once
// The range of each [sim] setting, written once: the scene reader refuses a
// typed value outside it, naming the key (scenes/sim_section.cpp), and
// check_sim_settings refuses one built in code (setting_checks.h); the
// [contact], [track] and [vehicle] keys' are force_setting_ranges.h's.
// Limits that depend on the joint or the wheel (slop < 0.01 R, a margin
// inside the wheel's half width, a run that starts and ends on the rails)
// are setting_checks' alone. Plain header: no Bullet.

#include <cmath>
#include <string>

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

}  // namespace railjoint
