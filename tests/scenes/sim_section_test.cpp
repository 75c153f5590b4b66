// The [sim] section of a scene file (scenes/sim_section.h): defaults, every
// key read, bad values rejected with the key and the allowed range, keys of
// the other mode refused.

#include <iostream>
#include <string>

#include <gtest/gtest.h>

#include "scenes/scene_file.h"
#include "support/input_error.h"

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
  EXPECT_EQ(scene.sim.mode(), SimMode::kinematic);
  EXPECT_DOUBLE_EQ(scene.sim.time_step_s, SimSettings{}.time_step_s);
  EXPECT_FALSE(scene.sim.kinematic()->preload_N.has_value());
}

TEST(SimSection, KeysAreRead) {
  const Scene scene = parse_scene(kScene, "test.toml", {"sim.time_step=5e-5", "sim.preload=2e5", "sim.internal_edge_fix=false"});
  EXPECT_DOUBLE_EQ(scene.sim.time_step_s, 5e-5);
  ASSERT_TRUE(scene.sim.kinematic()->preload_N.has_value());
  EXPECT_DOUBLE_EQ(*scene.sim.kinematic()->preload_N, 2e5);
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
                   "sim.radius_of_gyration=0.3", "sim.flat_approach=0.5", "contact.law=linear",
                   "contact.stiffness=1.5e9", "contact.damping=100", "sim.friction=0.3"});
  EXPECT_EQ(scene.sim.mode(), SimMode::inertial);
  EXPECT_DOUBLE_EQ(scene.sim.inertial()->wheel_load_N, 2e5);
  EXPECT_EQ(scene.sim.inertial()->horizontal, HorizontalMotion::free);
  ASSERT_TRUE(scene.sim.inertial()->carrier_mass_kg.has_value());
  EXPECT_DOUBLE_EQ(*scene.sim.inertial()->carrier_mass_kg, 1000.0);
  ASSERT_TRUE(scene.sim.inertial()->radius_of_gyration_m.has_value());
  EXPECT_DOUBLE_EQ(*scene.sim.inertial()->radius_of_gyration_m, 0.3);
  EXPECT_DOUBLE_EQ(scene.sim.inertial()->flat_approach_m, 0.5);
  ASSERT_TRUE((scene.sim.linear_contact() != nullptr));
  EXPECT_DOUBLE_EQ(scene.sim.linear_contact()->stiffness_N_per_m, 1.5e9);
  EXPECT_DOUBLE_EQ(scene.sim.linear_contact()->damping_N_s_per_m, 100.0);
  // Defaults of the inertial mode: the thesis's 112.5 kN, speed held, rigid, no flat.
  const Scene defaults = parse_scene(kScene, "test.toml", {"sim.mode=inertial"});
  EXPECT_DOUBLE_EQ(defaults.sim.inertial()->wheel_load_N, 112.5e3);
  EXPECT_EQ(defaults.sim.inertial()->horizontal, HorizontalMotion::held);
  EXPECT_FALSE((defaults.sim.linear_contact() != nullptr));
  EXPECT_DOUBLE_EQ(defaults.sim.inertial()->flat_approach_m, 0.0);
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

// Issue 15 row 2: sim.refined_time_step = 1e-300 ran forever (3.6 GB in
// 10 s): a step that small never advances the clock (t + dt == t once dt is
// below t * 1.1e-16). Steps are bounded per key, and the run as a whole by
// a budget of 1e6 steps: the simulated time over the fine step (every step
// refined, the worst case; refine_distance may refine them all).
TEST(SimSection, StepsTooSmallOrRunsTooLongAreRefusedByKey) {
  for (const char* key : {"sim.refined_time_step", "sim.time_step"}) {
    const std::string error = scene_error({std::string(key) + "=1e-300"});
    std::cout << error << "\n";
    EXPECT_EQ(error.rfind(std::string(key) + ": ", 0), 0u) << error;
    EXPECT_NE(error.find("must be in [1e-"), std::string::npos) << error;
  }
  // Slow and long: 40 m at 0.1 m/s is 400 s of simulated time, 4e8 steps of
  // 1e-6 s. The user set the approach: the message names it and its bound,
  // (1e6 x 1e-6 s - 0.002 s) x 0.1 m/s = 0.0998 m.
  std::string error = scene_error({"joint.length=100", "wheel.speed=0.1", "sim.approach_distance=40"});
  std::cout << error << "\n";
  EXPECT_EQ(error.rfind("sim.approach_distance: ", 0), 0u) << error;
  EXPECT_NE(error.find("0.0998 m"), std::string::npos) << error;
  // The user set the fine step: it is blamed, with T / 1e6 = 0.0502 s / 1e6.
  error = scene_error({"wheel.speed=1", "sim.refined_time_step=1e-8"});
  std::cout << error << "\n";
  EXPECT_EQ(error.rfind("sim.refined_time_step: ", 0), 0u) << error;
  EXPECT_NE(error.find("5.2e-08 s"), std::string::npos) << error;
  // Within the budget: the slowest wheel (0.1 m/s: 0.502 s, 5.02e5 steps),
  // and the convergence study's finest refined step at 50 m/s.
  EXPECT_EQ(scene_error({"wheel.speed=0.1"}), "");
  EXPECT_EQ(scene_error({"sim.refined_time_step=3e-7"}), "");
}

// Issue 15 row 7: a pair of [sim] keys that disagree blamed the key the user
// had not set, and printed "-sim.slop = -0 m".
TEST(SimSection, APairThatDisagreesBlamesTheKeyTheUserSet) {
  std::string error = scene_error({"sim.contact_processing_threshold=-1e-7"});
  std::cout << error << "\n";
  EXPECT_EQ(error.rfind("sim.contact_processing_threshold: ", 0), 0u) << error;
  EXPECT_EQ(error.find("-0 m"), std::string::npos) << error;
  EXPECT_NE(error.find("-sim.slop = 0 m"), std::string::npos) << error;
  error = scene_error({"sim.slop=1e-6", "sim.contact_processing_threshold=-2e-6"});
  EXPECT_NE(error.find("-sim.slop = -1e-06 m"), std::string::npos) << error;
  EXPECT_EQ(scene_error({"sim.slop=0"}), "");
  // A coarse step below the default fine step (1e-6 s): the user set the coarse one.
  error = scene_error({"sim.time_step=1e-7"});
  std::cout << error << "\n";
  EXPECT_EQ(error.rfind("sim.time_step: ", 0), 0u) << error;
  EXPECT_NE(error.find("sim.refined_time_step = 1e-06 s"), std::string::npos) << error;
  error = scene_error({"sim.refined_time_step=1e-3"});
  EXPECT_EQ(error.rfind("sim.refined_time_step: ", 0), 0u) << error;
  // The breaking threshold below the default refine distance (1e-5 m).
  error = scene_error({"sim.contact_breaking_threshold=1e-6"});
  std::cout << error << "\n";
  EXPECT_EQ(error.rfind("sim.contact_breaking_threshold: ", 0), 0u) << error;
  error = scene_error({"sim.refine_distance=0.01"});
  EXPECT_EQ(error.rfind("sim.refine_distance: ", 0), 0u) << error;
}

}  // namespace
}  // namespace railjoint
