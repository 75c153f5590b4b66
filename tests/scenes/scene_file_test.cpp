// Scene files: defaults, overrides and the errors a user sees.

#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "models/input_error.h"
#include "scenes/scene_file.h"

namespace railjoint {
namespace {

std::string error_of(const std::string& text, const std::vector<std::string>& overrides = {}) {
  try {
    parse_scene(text, "test.toml", overrides);
  } catch (const InputError& error) {
    return error.what();
  }
  return "no error";
}

TEST(SceneFile, EmptySceneTakesTheThesisDefaults) {
  const Scene scene = parse_scene("", "empty.toml");
  EXPECT_NEAR(scene.joint.theta_rad, std::numbers::pi / 6, 1e-15);
  EXPECT_EQ(scene.joint.beta_rad, 0.03);
  EXPECT_EQ(scene.wheel.radius_m, 0.475);
  EXPECT_EQ(scene.wheel.lateral_m, 0.015);
  EXPECT_EQ(scene.name, "empty");
}

TEST(SceneFile, KeysAreReadInSIUnitsAndDegrees) {
  const Scene scene = parse_scene(
      "[joint]\nkind = \"step\"\nstep_height = 0.002\ntheta_deg = 45\n[wheel]\nradius = 0.45\nspeed = 10\ny = 0\n",
      "s.toml");
  EXPECT_EQ(scene.joint.kind, JointKind::step);
  EXPECT_EQ(scene.joint.step_height_m, 0.002);
  EXPECT_NEAR(scene.joint.theta_rad, std::numbers::pi / 4, 1e-15);
  EXPECT_EQ(scene.wheel.radius_m, 0.45);
  EXPECT_EQ(scene.wheel.speed_m_per_s, 10.0);  // an integer is accepted for a number
}

TEST(SceneFile, OverridesReplaceFileValues) {
  const Scene scene = parse_scene("[wheel]\nspeed = 50.0\n", "o.toml", {"wheel.speed=30", "joint.kind=step"});
  EXPECT_EQ(scene.wheel.speed_m_per_s, 30.0);
  EXPECT_EQ(scene.joint.kind, JointKind::step);
}

TEST(SceneFile, OverridesTakeDecimalsAsAShellUserWritesThem) {
  // TOML refuses .005, 5. and 050; on the command line they mean 0.005, 5, 50.
  const Scene scene = parse_scene("", "test.toml",
                                  {"wheel.y=.005", "wheel.speed=+5.", "joint.theta_deg=050", "sim.solver_iterations=020"});
  EXPECT_EQ(scene.wheel.lateral_m, 0.005);
  EXPECT_EQ(scene.wheel.speed_m_per_s, 5.0);
  EXPECT_NEAR(scene.joint.theta_rad, 50.0 * std::numbers::pi / 180.0, 1e-15);
  EXPECT_EQ(scene.sim.solver_iterations, 20);  // an integer key takes 020 as an integer
  EXPECT_EQ(parse_scene("", "test.toml", {"wheel.y=+.005"}).wheel.lateral_m, 0.005);
  // Not a number end to end, or not finite: still an error naming the key.
  EXPECT_NE(error_of("", {"wheel.y=.005m"}).find("key 'wheel.y': --set value \".005m\" is not a valid number"),
            std::string::npos);
  EXPECT_NE(error_of("", {"wheel.speed=1e400"}).find("is not a valid number"), std::string::npos);
}

TEST(SceneFile, ANameThatIsNoTextIsAnError) {
  EXPECT_EQ(error_of("name = 5\n"), "test.toml: key 'name': must be a text in quotes, e.g. name = \"my joint\"");
  EXPECT_EQ(parse_scene("name = \"mine\"\n", "test.toml").name, "mine");
}

TEST(SceneFile, ErrorsNameFileKeyAndRange) {
  EXPECT_EQ(error_of("[joint]\ntheta = 30\n"), "test.toml: key 'joint.theta': unknown key in [joint]");
  EXPECT_EQ(error_of("[joint]\ntheta_deg = 120\n"), "test.toml: key 'joint.theta_deg': must be in (0, 90], got 120");
  EXPECT_EQ(error_of("[joint]\ntheta_deg = 0\n"), "test.toml: key 'joint.theta_deg': must be in (0, 90], got 0");
  EXPECT_EQ(error_of("[joint]\nbeta = -0.01\n"), "test.toml: key 'joint.beta': must be in [0, 1], got -0.01");
  EXPECT_EQ(error_of("[wheel]\nspeed = \"fast\"\n"),
            "test.toml: key 'wheel.speed': must be a number in [0.1, 1000], got a string");
  EXPECT_EQ(error_of("[wheel]\nmass = 0\n"), "test.toml: key 'wheel.mass': must be in (0, 10000000], got 0");
  EXPECT_EQ(error_of("[wheel]\nradius = -1\n"), "test.toml: key 'wheel.radius': must be in [0.05, 10], got -1");
  EXPECT_NE(error_of("[wheel]\ny = 0.025\n").find("test.toml: key 'wheel.y': lateral position must lie on the rail head"),
            std::string::npos);
  EXPECT_NE(error_of("[joint]\nkind = \"step\"\nstep_height = 0.5\n").find("key 'joint.step_height'"),
            std::string::npos);
  EXPECT_EQ(error_of("[joint]\nkind = \"square\"\n"),
            "test.toml: key 'joint.kind': must be one of \"inclined\", \"step\", got \"square\"");
  EXPECT_EQ(error_of("[wheels]\nradius = 1\n"), "test.toml: key 'wheels': unknown section");
  EXPECT_NE(error_of("[joint\n").find("test.toml: not valid TOML (line 1"), std::string::npos);
  EXPECT_NE(error_of("", {"wheel.speed"}).find("--set expects section.key=value"), std::string::npos);
  EXPECT_EQ(error_of("", {"wheel.speed=-3"}), "test.toml: key 'wheel.speed': must be in [0.1, 1000], got -3");
  EXPECT_EQ(error_of("[joint]\nhalf_width = inf\n"),
            "test.toml: key 'joint.half_width': must be a finite number in (0, 1], got inf");
  EXPECT_EQ(error_of("", {"sim.preload=inf"}), "test.toml: key 'sim.preload': must be a finite number in [0, 1000000000], got inf");
}

TEST(SceneFile, UnreadableFileIsNamed) {
  try {
    load_scene("/nonexistent/scene.toml");
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()), "/nonexistent/scene.toml: no such scene file");
  }
}

}  // namespace
}  // namespace railjoint
