// The [sim] section of a scene file (scenes/sim_section.h): defaults, every
// key read, bad values rejected with the key and the allowed range, keys of
// the other mode refused.

#include <string>

#include <gtest/gtest.h>

#include "models/input_error.h"
#include "scenes/scene_file.h"

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

TEST(SimSection, NarrowPhaseIsAKey) {
  EXPECT_EQ(parse_scene(kScene, "test.toml").sim.narrow_phase, NarrowPhase::exact);
  EXPECT_EQ(parse_scene(kScene, "test.toml", {"sim.narrow_phase=\"bullet\""}).sim.narrow_phase, NarrowPhase::bullet);
  EXPECT_NE(scene_error({"sim.narrow_phase=\"gjk\""}).find("sim.narrow_phase"), std::string::npos);
}

TEST(SimSection, BadValuesNameTheKey) {
  EXPECT_NE(scene_error({"sim.time_step=-1"}).find("sim.time_step"), std::string::npos);
  EXPECT_NE(scene_error({"sim.margin=0.5"}).find("sim.margin"), std::string::npos);
  EXPECT_NE(scene_error({"sim.restitution=2"}).find("sim.restitution"), std::string::npos);
  EXPECT_NE(scene_error({"sim.timestep=1e-4"}).find("sim.timestep"), std::string::npos);  // typo: unknown key
  EXPECT_NE(scene_error({"sim.mode=glued"}).find("sim.mode"), std::string::npos);
}

TEST(SimSection, InertialModeKeysAreRead) {
  const Scene scene =
      parse_scene(kScene, "test.toml",
                  {"sim.mode=inertial", "sim.wheel_load=2e5", "sim.horizontal=free", "sim.carrier_mass=1000",
                   "sim.radius_of_gyration=0.3", "sim.flat_approach=0.5", "sim.contact_stiffness=1.5e9",
                   "sim.contact_damping=100", "sim.friction=0.3"});
  EXPECT_EQ(scene.sim.mode, SimMode::inertial);
  EXPECT_DOUBLE_EQ(scene.sim.wheel_load_N, 2e5);
  EXPECT_EQ(scene.sim.horizontal, HorizontalMotion::free);
  ASSERT_TRUE(scene.sim.carrier_mass_kg.has_value());
  EXPECT_DOUBLE_EQ(*scene.sim.carrier_mass_kg, 1000.0);
  ASSERT_TRUE(scene.sim.radius_of_gyration_m.has_value());
  EXPECT_DOUBLE_EQ(*scene.sim.radius_of_gyration_m, 0.3);
  EXPECT_DOUBLE_EQ(scene.sim.flat_approach_m, 0.5);
  ASSERT_TRUE(scene.sim.contact_stiffness_N_per_m.has_value());
  EXPECT_DOUBLE_EQ(*scene.sim.contact_stiffness_N_per_m, 1.5e9);
  EXPECT_DOUBLE_EQ(scene.sim.contact_damping_N_s_per_m, 100.0);
  // Defaults of the inertial mode: the thesis's 112.5 kN, speed held, rigid, no flat.
  const Scene defaults = parse_scene(kScene, "test.toml", {"sim.mode=inertial"});
  EXPECT_DOUBLE_EQ(defaults.sim.wheel_load_N, 112.5e3);
  EXPECT_EQ(defaults.sim.horizontal, HorizontalMotion::held);
  EXPECT_FALSE(defaults.sim.contact_stiffness_N_per_m.has_value());
  EXPECT_DOUBLE_EQ(defaults.sim.flat_approach_m, 0.0);
}

TEST(SimSection, ModeSpecificKeysAreRejectedInTheOtherMode) {
  // A key that would be ignored is an error, never a silent default.
  EXPECT_NE(scene_error({"sim.wheel_load=1e5"}).find("sim.wheel_load"), std::string::npos);
  EXPECT_NE(scene_error({"sim.contact_stiffness=1e9"}).find("sim.contact_stiffness"), std::string::npos);
  EXPECT_NE(scene_error({"sim.mode=inertial", "sim.preload=1e5"}).find("sim.preload"), std::string::npos);
  EXPECT_NE(scene_error({"sim.mode=inertial", "sim.wheel_load=-1"}).find("sim.wheel_load"), std::string::npos);
  EXPECT_NE(scene_error({"sim.mode=inertial", "sim.horizontal=sideways"}).find("sim.horizontal"), std::string::npos);
  EXPECT_NE(scene_error({"sim.mode=inertial", "sim.contact_stiffness=0"}).find("sim.contact_stiffness"),
            std::string::npos);
}

}  // namespace
}  // namespace railjoint
