// Bad [sim] settings are rejected with the key and the allowed range, both
// when read from a scene file and when combined at the start of a run.

#include <string>

#include <gtest/gtest.h>

#include "models/parameter_error.h"
#include "scenes/input_error.h"
#include "scenes/scene_file.h"
#include "sim/crossing_cases.h"
#include "sim/simulate_crossing.h"

namespace railjoint {
namespace {

const char* kScene = R"(
[joint]
theta_deg = 30.0
[wheel]
y = 0.015
)";

std::string scene_error(const std::vector<std::string>& overrides) {
  try {
    parse_scene(kScene, "test.toml", overrides);
  } catch (const InputError& error) {
    return error.key() + ": " + error.what();
  }
  return "";
}

TEST(SimSection, AbsentSectionGivesTheDefaults) {
  const Scene scene = parse_scene(kScene, "test.toml");
  EXPECT_EQ(scene.sim.mode, SimMode::kinematic);
  EXPECT_DOUBLE_EQ(scene.sim.time_step_s, SimSettings{}.time_step_s);
  EXPECT_FALSE(scene.sim.preload_N.has_value());
}

TEST(SimSection, KeysAreRead) {
  const Scene scene = parse_scene(kScene, "test.toml", {"sim.time_step=5e-5", "sim.preload=2e5", "sim.internal_edge_fix=false"});
  EXPECT_DOUBLE_EQ(scene.sim.time_step_s, 5e-5);
  ASSERT_TRUE(scene.sim.preload_N.has_value());
  EXPECT_DOUBLE_EQ(*scene.sim.preload_N, 2e5);
  EXPECT_FALSE(scene.sim.internal_edge_fix);
}

TEST(SimSection, BadValuesNameTheKey) {
  EXPECT_NE(scene_error({"sim.time_step=-1"}).find("sim.time_step"), std::string::npos);
  EXPECT_NE(scene_error({"sim.margin=0.5"}).find("sim.margin"), std::string::npos);
  EXPECT_NE(scene_error({"sim.restitution=2"}).find("sim.restitution"), std::string::npos);
  EXPECT_NE(scene_error({"sim.timestep=1e-4"}).find("sim.timestep"), std::string::npos);  // typo: unknown key
  const std::string inertial = scene_error({"sim.mode=inertial"});
  EXPECT_NE(inertial.find("sim.mode"), std::string::npos);
  EXPECT_NE(inertial.find("not implemented"), std::string::npos);
}

std::string settings_error(const SimSettings& settings) {
  const CrossingCase c = inclined_crossing("s2", 30.0, 0.015);
  try {
    check_sim_settings(settings, c.joint, c.wheel);
  } catch (const ParameterError& error) {
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

}  // namespace
}  // namespace railjoint
