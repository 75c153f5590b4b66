// The labels of an FXAA frame (drawn by GL apart from the picture and laid
// over it after the smoothing, renders/read_back_frame.h) against those GL
// draws into the picture of a frame without anti-aliasing: on a flat
// background, where FXAA changes nothing, both must cover the same pixels
// with the same colours, and no label edge may come out smoothed.

#include <gtest/gtest.h>

#include "renders/offscreen_renderer.h"
#include "renders/text_overlay.h"

namespace railjoint {
namespace {

RgbImage drawn(const FrameDrawList& list, Antialiasing antialiasing) {
  OffscreenRenderer renderer(480, 160, antialiasing);
  RgbImage image;
  renderer.draw(list, image);
  return image;
}

TEST(OverlayLabels, AnFxaaFrameLaysThemCrispWhereAFrameWithoutAntialiasingDrawsThem) {
  const Eigen::Vector3f ink(0.1f, 0.2f, 0.3f), orange(1.0f, 0.5f, 0.0f);
  // Text and boxes at whole pixels, as the views lay them, and at fractions
  // of a pixel with slanted call-out lines, as the perspective view does.
  FrameDrawList list;
  list.background = {0.86f, 0.88f, 0.92f};
  append_rectangle(list.overlay, 4.0f, 4.0f, 300.0f, 40.0f, {1.0f, 1.0f, 1.0f});
  append_text(list.overlay, "IMPACT at t = 1.0000 ms: dp_z = 2149.50 N s", 8.0f, 8.0f, 2.0f, orange);
  append_text(list.overlay, "t = 1.0000 ms   wheel x = +5.897 mm", 8.0f, 50.0f, 1.0f, ink);
  append_outline(list.overlay, 320.0f, 10.0f, 470.0f, 150.0f, 2.0f, ink);
  append_text(list.overlay, "straightedge: dip 8.0 mm", 10.3f, 70.7f, 1.9f, ink);
  append_rectangle(list.overlay, 10.25f, 100.6f, 200.8f, 130.1f, {1.0f, 1.0f, 1.0f});
  append_line(list.overlay, {220.0f, 150.0f}, {470.0f, 60.0f}, 2.0f, ink);
  append_line(list.overlay, {230.0f, 20.0f}, {330.5f, 140.0f}, 1.0f, orange);
  const RgbImage plain = drawn(list, Antialiasing::none);
  long long covered = 0;  // the background's red is 0.86 x 255 = 219
  for (std::size_t i = 0; i < plain.rgb.size(); i += 3) covered += plain.rgb[i] != 219 ? 1 : 0;
  EXPECT_GT(covered, 5000) << "the labels must cover enough pixels to mean something";
  EXPECT_EQ(drawn(list, Antialiasing::fxaa).rgb, plain.rgb);
}

}  // namespace
}  // namespace railjoint
