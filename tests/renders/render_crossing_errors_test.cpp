// render_crossing refuses bad input with a clear message before it draws or
// writes anything. These run with or without a GL back end: every check comes before
// the GL context. In a build without OSMesa, valid input gets the
// "rendering unavailable" error instead of a crash.

#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

#include <gtest/gtest.h>

#include "geometry/rail_joint_mesh.h"
#include "geometry/wheel_mesh.h"
#include "models/input_error.h"
#include "renders/render_crossing.h"
#include "tests/support/scratch_dir.h"

namespace railjoint {
namespace {

struct Inputs {
  RailJointMesh rails = build_rail_joint_mesh(JointParams{});
  TriangleMesh wheel = build_wheel_mesh(WheelParams{}, 32);
  Trajectory trajectory;
  Inputs() {
    for (int i = 0; i <= 10; ++i) {
      WheelSample s;
      s.time_s = i * 1e-4;
      s.centre_m = {-0.2 + 0.005 * i, 0.015, 0.478};
      trajectory.samples.push_back(s);
    }
  }
};

std::filesystem::path scratch_dir(const std::string& name) {
  return testing_support::scratch_path(name);
}

std::string parameter_key(const RenderSettings& settings, const std::filesystem::path& out) {
  const Inputs in;
  try {
    render_crossing(settings, in.rails, in.wheel, in.trajectory, out);
  } catch (const InputError& error) {
    std::cout << "  " << error.key() << ": " << error.what() << "\n";
    return error.key();
  }
  return "none";
}

TEST(RenderCrossingErrors, ZeroImageSizeIsAnInputErrorAndWritesNothing) {
  const auto out = scratch_dir("size");
  RenderSettings s;
  s.width_px = 0;
  s.ffmpeg = false;
  EXPECT_EQ(parameter_key(s, out), "render.width");
  EXPECT_FALSE(std::filesystem::exists(out)) << "nothing may be created for refused settings";
}

TEST(RenderCrossingErrors, NegativeFpsIsAnInputError) {
  RenderSettings s;
  s.fps = -100.0;
  s.ffmpeg = false;
  EXPECT_EQ(parameter_key(s, scratch_dir("fps")), "render.fps");
}

TEST(RenderCrossingErrors, UnwritableOutputFolderIsNamedInTheError) {
  // A regular file where a folder should be: no folder can be created below
  // it, whoever runs the test (permission bits do not stop root).
  const auto base = scratch_dir("unwritable");
  std::filesystem::create_directories(base);
  const auto blocker = base / "not_a_folder";
  std::ofstream(blocker) << "x";
  const auto out = blocker / "frames";
  RenderSettings s;
  s.fps = 10000;
  s.ffmpeg = false;
  const Inputs in;
  try {
    render_crossing(s, in.rails, in.wheel, in.trajectory, out);
    FAIL() << "expected an error for " << out;
  } catch (const std::runtime_error& error) {
    const std::string message = error.what();
    std::cout << "  " << message << "\n";
    EXPECT_NE(message.find(out.string()), std::string::npos) << "the message must name the folder";
  }
}

TEST(RenderCrossingErrors, MismatchedFaceTagsAreRefused) {
  Inputs in;
  in.wheel.tags.pop_back();
  RenderSettings s;
  s.ffmpeg = false;
  EXPECT_THROW(render_crossing(s, in.rails, in.wheel, in.trajectory, scratch_dir("tags")), std::invalid_argument);
}

#if !RAILJOINT_TEST_HAVE_GL
TEST(RenderCrossingErrors, WithoutAGlBackEndUseSaysRenderingIsUnavailable) {
  const Inputs in;
  RenderSettings s;
  s.fps = 10000;
  s.ffmpeg = false;
  try {
    render_crossing(s, in.rails, in.wheel, in.trajectory, scratch_dir("no_gl"));
    FAIL() << "a build without OSMesa cannot render";
  } catch (const std::runtime_error& error) {
    std::cout << "  " << error.what() << "\n";
    EXPECT_NE(std::string(error.what()).find("rendering unavailable: built without OSMesa"), std::string::npos);
  }
}
#endif

}  // namespace
}  // namespace railjoint
