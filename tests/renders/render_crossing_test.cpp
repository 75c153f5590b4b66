// render_crossing end to end: frame files, their count, the wheel moving
// across them, and the videos. Needs a GL back end.

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>

#include <gtest/gtest.h>
#include <stb_image.h>

#include "geometry/rail_joint_mesh.h"
#include "geometry/wheel_mesh.h"
#include "renders/render_crossing.h"
#include "renders/video_assembly.h"
#include "tests/support/scratch_dir.h"

namespace railjoint {
namespace {

// The wheel rolls from x = -0.25 m to -0.15 m in 1 ms (100 m/s) on the
// incoming rail z = -t x, t = tan(beta/2): resting on it, its centre is at
// z = -t x + R sqrt(1 + t^2) (see crossing_render_test.cpp).
Trajectory rolling() {
  Trajectory t;
  for (int i = 0; i <= 100; ++i) {
    WheelSample s;
    s.time_s = i * 1e-5;
    const double x = -0.25 + 0.1 * i / 100.0;
    const double t_half = std::tan(0.015);
    s.centre_m = {x, 0.015, -t_half * x + 0.475 * std::sqrt(1.0 + t_half * t_half)};
    s.velocity_m_per_s = {100.0, 0.0, 0.0};
    s.spin_angle_rad = (x + 0.25) / 0.475;
    t.samples.push_back(s);
  }
  return t;
}

// 320 x 240 px, side view, 2.4 m wide: 133.33 px/m; heights x20 (the
// default), so the wheel is drawn as an ellipse 127 px wide and 2,533 px
// tall, its lowest point at the image centre.
RenderSettings small_side_view() {
  RenderSettings s;
  s.width_px = 320;
  s.height_px = 240;
  s.view_width_m = 2.4;
  s.fps = 10000;
  s.follow_wheel = false;
  s.ffmpeg = false;
  return s;
}

std::filesystem::path fresh_dir(const std::string& name) {
  return testing_support::scratch_path(name);
}

// Mean column (+ 0.5) of the clear-blue (wheel) pixels of a PNG file.
double wheel_centroid_u(const std::filesystem::path& png) {
  int w = 0, h = 0, n = 0;
  unsigned char* pixels = stbi_load(png.c_str(), &w, &h, &n, 3);
  if (pixels == nullptr) {
    ADD_FAILURE() << "cannot read " << png;
    return NAN;
  }
  double sum = 0.0;
  long long count = 0;
  for (int i = 0; i < w * h; ++i) {
    const unsigned char* p = pixels + 3 * i;
    if (p[2] >= p[0] + 40 && p[2] >= p[1] + 40) {
      sum += (i % w) + 0.5;
      ++count;
    }
  }
  stbi_image_free(pixels);
  return count > 0 ? sum / static_cast<double>(count) : NAN;
}

TEST(RenderCrossing, ShortRunWritesOneFilePerFrameAndTheWheelMovesForward) {
  const RailJointMesh rails = build_rail_joint_mesh(JointParams{});
  const TriangleMesh wheel = build_wheel_mesh(WheelParams{}, 128);
  const auto out = fresh_dir("short_run") / "nested" / "frames";  // created, parents too
  const RenderReport report = render_crossing(small_side_view(), rails, wheel, rolling(), out);
  std::cout << "frames " << report.frames_written << ", render " << report.render_ms_per_frame << " ms/frame, encode "
            << report.encode_ms_per_frame << " ms/frame, GL " << report.gl_version << "; " << report.video_note
            << "\n";

  // Window 1 ms (the whole trajectory) at 10000 frames per simulated second:
  // 10 periods, frames at 0, 0.1, ..., 1.0 ms -> 11 files, frame_00000 .. frame_00010.
  EXPECT_EQ(report.frames_written, 11);
  for (int k = 0; k <= 10; ++k) EXPECT_TRUE(std::filesystem::exists(out / frame_file_name(k))) << k;
  EXPECT_FALSE(std::filesystem::exists(out / frame_file_name(11)));
  EXPECT_EQ(frame_file_name(7), "frame_00007.png");
  EXPECT_FALSE(report.mp4.has_value());
  EXPECT_FALSE(report.video_note.empty());

  // Fixed camera: the wheel moves 0.01 m per frame = 1.333 px to the right;
  // 0.1 m = 13.33 px over the run.
  double previous = -1.0;
  const double first = wheel_centroid_u(out / frame_file_name(0));
  for (int k = 0; k <= 10; ++k) {
    const double u = wheel_centroid_u(out / frame_file_name(k));
    std::cout << "frame " << k << ": wheel centroid u = " << u << " px\n";
    EXPECT_GT(u, previous) << "frame " << k << " must show the wheel further along x";
    previous = u;
  }
  // 1 px: the visible part of the ellipse (below the label box, above the
  // rails, which touch it without hiding any of it) is symmetric about the
  // wheel's x, so its centroid follows x to a fraction of a pixel.
  EXPECT_NEAR(previous - first, 0.1 * 320.0 / 2.4, 1.0);
}

// Issue 29, item 9: in a flight the side view followed the wheel's lowest
// point and the rails fell out of the frame. A wheel flying 5 mm over the
// outgoing rail (x20: 100 mm drawn, the default view is 135 mm x 76 mm at
// 16:9): the frame shows the rail under it, and the wheel.
TEST(RenderCrossing, AFlyingWheelIsDrawnWithTheRailUnderIt) {
  const JointParams joint{};
  const double slope = std::tan(0.5 * joint.beta_rad);
  Trajectory flight;
  for (int i = 0; i <= 2; ++i) {
    WheelSample s;
    s.time_s = 1e-4 * i;
    const double x = 0.2 + 0.005 * i;
    s.centre_m = Eigen::Vector3d(x, 0.015, 0.475 + x * slope + 0.005);
    s.velocity_m_per_s = Eigen::Vector3d(50.0, 0.0, 0.0);
    flight.samples.push_back(s);
  }
  RenderSettings s;
  s.width_px = 640;
  s.height_px = 360;
  s.fps = 10000;
  s.ffmpeg = false;
  s.gltf = false;
  s.t_start_s = 1e-4;
  s.t_end_s = 1.5e-4;  // one frame, at 0.1 ms
  const auto out = fresh_dir("flying");
  render_crossing(s, build_rail_joint_mesh(joint), build_wheel_mesh(WheelParams{}, 256), flight, out);
  int w = 0, h = 0, n = 0;
  unsigned char* pixels = stbi_load((out / frame_file_name(0)).c_str(), &w, &h, &n, 3);
  ASSERT_NE(pixels, nullptr);
  long long rail = 0, wheel = 0;
  for (int i = 0; i < w * h; ++i) {
    const unsigned char* p = pixels + 3 * i;
    if (i / w >= static_cast<int>(0.75 * h)) continue;  // the label box below
    if (p[2] >= p[0] + 40 && p[2] >= p[1] + 40) ++wheel;  // clear blue
    // The rail's side, grey (palette::rail_side, darker on the outgoing rail).
    if (std::abs(p[0] - p[1]) < 16 && std::abs(p[1] - p[2]) < 16 && p[0] > 60 && p[0] < 200) ++rail;
  }
  stbi_image_free(pixels);
  std::cout << "wheel " << wheel << " px, rail " << rail << " px of " << w * h << "\n";
  EXPECT_GT(wheel, w * h / 50);
  EXPECT_GT(rail, w * h / 50) << "the rail under the flying wheel is out of the frame";
}

TEST(RenderCrossing, WindowAndFpsDecideTheFrameCount) {
  // 0.35 ms .. 0.8 ms at 20000 fps: 9 periods -> 10 frames.
  const RailJointMesh rails = build_rail_joint_mesh(JointParams{});
  const TriangleMesh wheel = build_wheel_mesh(WheelParams{}, 32);
  RenderSettings s = small_side_view();
  s.width_px = 64;
  s.height_px = 48;
  s.fps = 20000;
  s.t_start_s = 0.35e-3;
  s.t_end_s = 0.8e-3;
  const RenderReport report = render_crossing(s, rails, wheel, rolling(), fresh_dir("window"));
  EXPECT_EQ(report.frames_written, 10);
}

TEST(RenderCrossing, AssemblesMp4AndGifWhenFfmpegIsOnPath) {
  if (!find_on_path("ffmpeg")) GTEST_SKIP() << "ffmpeg is not on PATH here";
  const RailJointMesh rails = build_rail_joint_mesh(JointParams{});
  const TriangleMesh wheel = build_wheel_mesh(WheelParams{}, 64);
  RenderSettings s = small_side_view();
  s.ffmpeg = true;
  const auto out = fresh_dir("video");
  const RenderReport report = render_crossing(s, rails, wheel, rolling(), out);
  std::cout << report.video_note << " (" << report.video_wall_s << " s)\n";
  ASSERT_TRUE(report.mp4.has_value()) << report.video_note;
  ASSERT_TRUE(report.gif.has_value()) << report.video_note;
  EXPECT_GT(std::filesystem::file_size(*report.mp4), 1000u);
  EXPECT_GT(std::filesystem::file_size(*report.gif), 1000u);
  EXPECT_EQ(report.frames_written, 11);  // the frames stay
}

TEST(RenderCrossing, WithoutFfmpegTheReportSaysSoAndKeepsTheFrames) {
  const std::string saved = std::getenv("PATH") != nullptr ? std::getenv("PATH") : "";
  setenv("PATH", "/nonexistent-railjoint-test", 1);
  const RailJointMesh rails = build_rail_joint_mesh(JointParams{});
  const TriangleMesh wheel = build_wheel_mesh(WheelParams{}, 32);
  RenderSettings s = small_side_view();
  s.ffmpeg = true;
  const auto out = fresh_dir("no_ffmpeg");
  const RenderReport report = render_crossing(s, rails, wheel, rolling(), out);
  setenv("PATH", saved.c_str(), 1);
  std::cout << report.video_note << "\n";
  EXPECT_FALSE(report.mp4.has_value());
  EXPECT_FALSE(report.gif.has_value());
  EXPECT_NE(report.video_note.find("ffmpeg not found"), std::string::npos);
  EXPECT_EQ(report.frames_written, 11);
  EXPECT_TRUE(std::filesystem::exists(out / frame_file_name(10)));
}

}  // namespace
}  // namespace railjoint
