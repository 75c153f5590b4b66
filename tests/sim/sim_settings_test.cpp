// Bad combinations of [sim] settings are rejected at the start of a run with
// the key and the allowed range (sim/setting_checks.h).

#include <gtest/gtest.h>

#include <string>

#include "models/input_error.h"
#include "sim/crossing_cases.h"
#include "sim/setting_checks.h"
#include "sim/simulate_crossing.h"

namespace railjoint {
namespace {

std::string settings_error(const SimSettings& settings) {
  const CrossingCase c = inclined_crossing("s2", 30.0, 0.015);
  try {
    check_sim_settings(settings, c.joint, c.wheel);
  } catch (const InputError& error) {
    return error.key();
  }
  return "";
}

TEST(SimSettingsCheck, CombinationsAreChecked) {
  EXPECT_EQ(settings_error(SimSettings{}), "");
  SimSettings s;
  s.refined_time_step_s = 2 * s.time_step_s;
  EXPECT_EQ(settings_error(s), "sim.refined_time_step");
  s = SimSettings{};
  s.margin_m = s.disc_half_width_m;  // Bullet's cylinder keeps its margin inside the half width
  EXPECT_EQ(settings_error(s), "sim.margin");
  s = SimSettings{};
  s.contact_processing_threshold_m = -2 * s.slop_m;  // resting contacts would never be solved
  EXPECT_EQ(settings_error(s), "sim.contact_processing_threshold");
  s = SimSettings{};
  s.approach_distance_m = 0.45;  // starts beyond the incoming rail's 0.5 m minus the run-up
  EXPECT_EQ(settings_error(s), "sim.approach_distance");
}

TEST(SimSettingsCheck, InertialCombinationsAreChecked) {
  SimSettings s;
  s.make_inertial();
  EXPECT_EQ(settings_error(s), "");
  // A preload in inertial mode cannot be built (KinematicSettings holds it);
  // the scene reader refuses the key there (sim_section_test).
  s.make_inertial().radius_of_gyration_m = 1.0;  // beyond R = 0.475 m
  EXPECT_EQ(settings_error(s), "sim.radius_of_gyration");
  s = SimSettings{};
  // Past the stiffest contact a scene may give (1e12 N/m, setting_ranges.h).
  s.make_inertial().contact.emplace<LinearContactSettings>().stiffness_N_per_m = 1e13;
  EXPECT_EQ(settings_error(s), "contact.stiffness");
  // omega = sqrt(1e12 / 750) = 3.65e4 rad/s: the default 1e-6 s fine step is
  // 0.037 rad, inside the 0.05 limit; a 1e-5 s one is 0.37 rad.
  s.make_inertial().contact.emplace<LinearContactSettings>().stiffness_N_per_m = 1e12;
  EXPECT_EQ(settings_error(s), "");
  s.refined_time_step_s = 1e-5;
  EXPECT_EQ(settings_error(s), "sim.refined_time_step");
  s.refined_time_step_s = SimSettings{}.refined_time_step_s;
  s.make_inertial().contact.emplace<LinearContactSettings>().stiffness_N_per_m = 1.5e9;
  EXPECT_EQ(settings_error(s), "");
  s.make_inertial().flat_approach_m = 0.01;  // too short to start on
  EXPECT_EQ(settings_error(s), "sim.flat_approach");
}

}  // namespace
}  // namespace railjoint
