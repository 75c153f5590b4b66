// RenderSettings checks: every bad value is refused with the scene key and
// the allowed range, before any GL context or file exists.

#include <iostream>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "renders/render_settings.h"
#include "support/input_error.h"

namespace railjoint {
namespace {

// The key and message of the InputError check_render_settings throws, or "none".
std::string error_of(const RenderSettings& settings, std::string* message = nullptr) {
  try {
    check_render_settings(settings);
  } catch (const InputError& error) {
    if (message != nullptr) *message = error.what();
    std::cout << "  " << error.key() << ": " << error.what() << "\n";
    return error.key();
  }
  return "none";
}

TEST(RenderSettings, DefaultsAreAccepted) { EXPECT_EQ(error_of(RenderSettings{}), "none"); }

TEST(RenderSettings, ZeroOrHugeImageSizeIsRefusedWithTheRange) {
  RenderSettings zero_width;
  zero_width.width_px = 0;
  std::string message;
  EXPECT_EQ(error_of(zero_width, &message), "render.width");
  EXPECT_NE(message.find("[16, 8192]"), std::string::npos) << message;

  RenderSettings zero_height;
  zero_height.height_px = 0;
  EXPECT_EQ(error_of(zero_height), "render.height");

  RenderSettings huge;
  huge.width_px = 8193;
  EXPECT_EQ(error_of(huge), "render.width");

  RenderSettings smallest;  // both limits are inclusive
  smallest.width_px = 16;
  smallest.height_px = 8192;
  EXPECT_EQ(error_of(smallest), "none");
}

TEST(RenderSettings, NonPositiveFpsIsRefused) {
  for (double fps : {-1.0, 0.0, std::numeric_limits<double>::quiet_NaN()}) {
    RenderSettings s;
    s.fps = fps;
    EXPECT_EQ(error_of(s), "render.fps") << fps;
  }
}

TEST(RenderSettings, ExaggerationOutsideOneToTenThousandIsRefused) {
  for (double k : {0.5, 0.0, -20.0, 1e4 + 1.0}) {
    RenderSettings s;
    s.exaggeration = k;
    EXPECT_EQ(error_of(s), "render.exaggeration") << k;
  }
  RenderSettings one;
  one.exaggeration = 1.0;
  EXPECT_EQ(error_of(one), "none");
}

TEST(RenderSettings, WindowMustEndAfterItStarts) {
  RenderSettings s;
  s.t_start_s = 0.002;
  s.t_end_s = 0.002;
  EXPECT_EQ(error_of(s), "render.t_end");
  s.t_end_s = 0.001;
  EXPECT_EQ(error_of(s), "render.t_end");
}

TEST(RenderSettings, ViewWidthAndVideoRateMustBePositive) {
  RenderSettings width;
  width.view_width_m = 0.0;
  EXPECT_EQ(error_of(width), "render.view_width");
  RenderSettings video;
  video.video_fps = -25.0;
  EXPECT_EQ(error_of(video), "render.video_fps");
}

}  // namespace
}  // namespace railjoint
