// Sides of the render wheel: enough that its facets, drawn k-fold at the
// contact, stay below a quarter pixel.

#include <cmath>
#include <iostream>
#include <stdexcept>
#include <numbers>

#include <gtest/gtest.h>

#include "renders/wheel_tessellation.h"

namespace railjoint {
namespace {

// Drawn gap between the inscribed N-gon and the circle at the contact [px]:
// k s R (1 - cos(pi / N)), s = width / W px/m.
double drawn_gap_px(const RenderSettings& s, double R, int n) {
  const double px_per_m = s.width_px / s.view_width_m.value_or(kDefaultContactViewWidth_m);
  return s.exaggeration * px_per_m * R * (1.0 - std::cos(std::numbers::pi / n));
}

TEST(WheelTessellation, DefaultContactViewNeedsAboutFourteenHundredSides) {
  // 1280 px over 0.12 m (10,667 px/m), k = 20, R = 0.475 m: k s R = 101,333 px,
  // 1 - cos(pi/N) ~ pi^2 / (2 N^2) <= 0.25 / 101,333  =>  N >= pi / sqrt(2 * 2.467e-6) = 1414.3.
  const RenderSettings s;
  const int n = wheel_render_segments(s, 0.475);
  std::cout << "N = " << n << ", drawn gap " << drawn_gap_px(s, 0.475, n) << " px, with N - 1: "
            << drawn_gap_px(s, 0.475, n - 1) << " px\n";
  EXPECT_EQ(n, 1415);
  EXPECT_LE(drawn_gap_px(s, 0.475, n), 0.25);
  EXPECT_GT(drawn_gap_px(s, 0.475, n - 1), 0.25);  // the smallest such N
}

TEST(WheelTessellation, WideUnexaggeratedViewsAreClampedToTheMinimum) {
  RenderSettings s;
  s.exaggeration = 1.0;
  s.view_width_m = 2.4;  // 533 px/m: k s R = 253 px -> N >= pi / sqrt(2 * 0.25 / 253) = 70.7
  EXPECT_EQ(wheel_render_segments(s, 0.475), 71);
  s.width_px = 64;  // 26.7 px/m: N >= 22.5 -> clamped to 64
  EXPECT_EQ(wheel_render_segments(s, 0.475), kMinWheelRenderSegments);
  s.exaggeration = 1e4;
  s.width_px = 8192;
  s.view_width_m = 0.01;  // far beyond any sensible facet count
  EXPECT_EQ(wheel_render_segments(s, 0.475), kMaxWheelRenderSegments);
}

TEST(WheelTessellation, ACircleDrawnAThousandPixelsWideNeeds141Sides) {
  // r (1 - cos(pi / N)) <= 0.25 px at r = 1000 px: 1 - cos(pi/N) ~ pi^2 / (2 N^2)
  // <= 2.5e-4  =>  N >= pi / sqrt(5e-4) = 140.5; with N = 141 the gap is
  // 0.248 px, with 140 it is 0.252 px.
  const int n = polygon_sides_for_radius_px(1000.0);
  EXPECT_EQ(n, 141);
  EXPECT_LE(1000.0 * (1.0 - std::cos(std::numbers::pi / n)), 0.25);
  EXPECT_GT(1000.0 * (1.0 - std::cos(std::numbers::pi / (n - 1))), 0.25);
  EXPECT_EQ(polygon_sides_for_radius_px(100.0), kMinWheelRenderSegments);  // needs 45
  EXPECT_THROW(polygon_sides_for_radius_px(0.0), std::invalid_argument);
  EXPECT_THROW(polygon_sides_for_radius_px(10.0, -1.0), std::invalid_argument);
}

}  // namespace
}  // namespace railjoint
