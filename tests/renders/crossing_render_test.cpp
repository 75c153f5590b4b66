// Pixels of rendered frames against where the camera conventions
// (renders/camera.h) put things. Needs OSMesa.
//
// Test frame: 640 x 480 px, side view, view_width 2.4 m -> 266.67 px/m both
// ways (visible height 2.4 * 480 / 640 = 1.8 m). Exaggeration k = 20 about
// z_ref = 0. A world point (x, z) drawn at z' lands at pixel coordinates
//   u = 320 + (x - x_c) * 266.67,   v = 240 - (z' - 0.75 R) * 266.67
// (u right, v down from the top-left corner; pixel column i covers [i, i+1),
// so the mean of (i + 0.5) over a shape estimates u of its centroid).
//
// Joint: the thesis's default (theta 30 deg, beta 0.03 rad, b_t 20 mm,
// L = 1 m, depth 50 mm); wheel R = 0.475 m at y_w = 15 mm. The linear dip:
// the rail top at x is tan(beta/2) |x| (incoming rail for x < cut, outgoing
// beyond; both rise away from the V bottom at x = 0), so a wheel resting on
// it at x has its centre at z = R + tan(beta/2) |x|, drawn (VerticalExaggeration)
// at z' = R + k tan(beta/2) |x|.

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "geometry/rail_joint_mesh.h"
#include "geometry/wheel_mesh.h"
#include "renders/crossing_renderer.h"
#include "renders/png_file.h"

namespace railjoint {
namespace {

constexpr double kR = 0.475;
constexpr double kYw = 0.015;
constexpr double kK = 20.0;
constexpr int kW = 640;
constexpr int kH = 480;
constexpr double kPxPerM = 640.0 / 2.4;
const double kTanHalfBeta = std::tan(0.015);

double resting_centre_z(double x) { return kR + kTanHalfBeta * std::abs(x); }
double drawn_resting_centre_z(double x) { return kR + kK * kTanHalfBeta * std::abs(x); }
double pixel_u(double x, double x_centre) { return kW / 2.0 + (x - x_centre) * kPxPerM; }
double pixel_v(double z_drawn) { return kH / 2.0 - (z_drawn - 0.75 * kR) * kPxPerM; }

RenderSettings test_settings() {
  RenderSettings s;
  s.width_px = kW;
  s.height_px = kH;
  s.view = RenderView::side;
  s.view_width_m = 2.4;
  s.exaggeration = kK;
  s.follow_wheel = false;  // centred on the middle of the wheel's x range
  s.fps = 10000;
  s.ffmpeg = false;
  return s;
}

WheelSample resting_at(double t, double x, double spin = 0.0) {
  WheelSample s;
  s.time_s = t;
  s.centre_m = {x, kYw, resting_centre_z(x)};
  s.velocity_m_per_s = {100.0, 0.0, 0.0};
  s.spin_angle_rad = spin;
  return s;
}

// The wheel rolls on one rail from x0 to x1 over 1 ms (both on the same side
// of the V, so the drawn centre path is a straight line and the linear
// interpolation between the two samples is exact).
Trajectory rolling(double x0, double x1, double spin0 = 0.0, double spin1 = 0.0) {
  Trajectory t;
  t.samples = {resting_at(0.0, x0, spin0), resting_at(1e-3, x1, spin1)};
  return t;
}

struct Scene {
  RailJointMesh rails = build_rail_joint_mesh(JointParams{});
  // 256 sides: the inscribed polygon's centroid is the centre, its area
  // within 0.01 % of the circle's.
  TriangleMesh wheel = build_wheel_mesh(WheelParams{}, 256);
};

// Pixel classes by hue (renders/palette.h): the wheel is the only thing drawn
// in clear blues.
bool is_wheel(const std::uint8_t* p) { return p[2] >= p[0] + 40 && p[2] >= p[1] + 40; }
bool is_spoke(const std::uint8_t* p) { return is_wheel(p) && p[2] < 140; }  // the dark bar and knob
bool is_background(const std::uint8_t* p) {
  // palette::background (0.93, 0.95, 0.98) as 8 bits.
  return std::abs(p[0] - 237) <= 1 && std::abs(p[1] - 242) <= 1 && std::abs(p[2] - 250) <= 1;
}
bool is_impact_orange(const std::uint8_t* p) { return p[0] > 230 && p[1] > 90 && p[1] < 140 && p[2] < 30; }

struct Centroid {
  double u = 0.0, v = 0.0;
  long long count = 0;
};

template <class Predicate>
Centroid centroid(const RgbImage& image, Predicate is) {
  Centroid c;
  for (int row = 0; row < image.height_px; ++row) {
    for (int col = 0; col < image.width_px; ++col) {
      if (!is(image.pixel(col, row))) continue;
      c.u += col + 0.5;
      c.v += row + 0.5;
      ++c.count;
    }
  }
  if (c.count > 0) {
    c.u /= static_cast<double>(c.count);
    c.v /= static_cast<double>(c.count);
  }
  return c;
}

TEST(CrossingRender, ContextReportsItsGlVersion) {
  const Scene scene;
  CrossingRenderer renderer(test_settings(), scene.rails, scene.wheel, rolling(-0.25, -0.15));
  std::cout << "GL_VERSION " << renderer.gl_version() << ", GL_RENDERER " << renderer.gl_renderer() << "\n";
  RecordProperty("gl_version", renderer.gl_version());
  // We asked for a 3.3 core profile; Mesa gives the newest it has (4.5 here).
  ASSERT_GE(renderer.gl_version().size(), 3u);
  EXPECT_GE(renderer.gl_version()[0], '3');
}

class WheelOnEitherRail : public ::testing::TestWithParam<double> {};

// One frame of a known state: the wheel where the projection says, the rail
// top edge (on the other rail, clear of the wheel) where the profile says.
TEST_P(WheelOnEitherRail, WheelCentroidAndRailTopEdgeLandWhereTheProjectionSays) {
  const double side = GetParam();  // -1: wheel on the incoming rail, +1: on the outgoing one
  const double x0 = side * 0.25, x1 = side * 0.15;
  const Scene scene;
  CrossingRenderer renderer(test_settings(), scene.rails, scene.wheel, rolling(x0, x1));
  const double x_centre = 0.5 * (x0 + x1);  // fixed camera: middle of the wheel's x range

  // A quarter of the way through: x = x0 + (x1 - x0) / 4.
  RgbImage image;
  renderer.render_at(0.25e-3, image);
  const double x = x0 + 0.25 * (x1 - x0);

  long long drawn = 0;
  for (int row = 0; row < kH; ++row)
    for (int col = 0; col < kW; ++col) drawn += is_background(image.pixel(col, row)) ? 0 : 1;
  std::cout << "non-background pixels: " << drawn << " of " << kW * kH << "\n";
  EXPECT_GT(drawn, kW * kH / 5) << "the frame is (nearly) blank";

  const Centroid wheel = centroid(image, is_wheel);
  const double u = pixel_u(x, x_centre), v = pixel_v(drawn_resting_centre_z(x));
  std::cout << "wheel centroid (" << wheel.u << ", " << wheel.v << ") px from " << wheel.count
            << " pixels; projection of the centre (" << u << ", " << v << ")\n";
  // The disc covers pi (R * 266.67 px/m)^2 = 50,400 px.
  EXPECT_NEAR(static_cast<double>(wheel.count), std::numbers::pi * std::pow(kR * kPxPerM, 2), 0.02 * 50400);
  // Tolerance 2 px: the exaggerated rail (slope k tan(beta/2) = 0.3) cuts a
  // sliver of about 0.5 % of the disc off beside the contact, which moves the
  // centroid of what stays visible by ~0.7 px; rasterisation adds up to 0.5 px.
  EXPECT_NEAR(wheel.u, u, 2.0);
  EXPECT_NEAR(wheel.v, v, 2.0);

  // Rail top edge on the other rail, at columns clear of the wheel (which
  // spans x +- 0.475 m): the first non-background pixel from the top of the
  // column is where the top face is seen edge-on, drawn at k tan(beta/2) |x|.
  for (double xr : {-0.45, -0.4, -0.35, -0.3}) {
    const double x_rail = -side * std::abs(xr);
    const int col = static_cast<int>(std::floor(pixel_u(x_rail, x_centre)));
    int first = -1;
    // From row 60 down: the label lines above it (top-left) are not rail.
    for (int row = 60; row < kH && first < 0; ++row)
      if (!is_background(image.pixel(col, row))) first = row;
    // Column centre x (not the column's left edge) decides the expected row.
    const double x_col = x_centre + (col + 0.5 - kW / 2.0) / kPxPerM;
    const double v_edge = pixel_v(kK * kTanHalfBeta * std::abs(x_col));
    std::cout << "column " << col << " (x = " << x_col << " m): rail top edge at row " << first
              << ", profile says v = " << v_edge << "\n";
    // The first covered row is the one whose centre lies below the edge:
    // ceil(v - 0.5); 1 px for rasterisation of the slanted edge.
    EXPECT_NEAR(first, std::ceil(v_edge - 0.5), 1.0);
  }
}

INSTANTIATE_TEST_SUITE_P(Rails, WheelOnEitherRail, ::testing::Values(-1.0, 1.0));

TEST(CrossingRender, SameInputGivesByteIdenticalImagesAndFiles) {
  const Scene scene;
  const Trajectory t = rolling(-0.25, -0.15, 0.0, 0.3);
  RgbImage a, b, c;
  {
    CrossingRenderer renderer(test_settings(), scene.rails, scene.wheel, t);
    renderer.render_at(0.4e-3, a);
    renderer.render_at(0.9e-3, c);  // something else in between
    renderer.render_at(0.4e-3, b);
  }
  RgbImage fresh;  // a second context
  CrossingRenderer other(test_settings(), scene.rails, scene.wheel, t);
  other.render_at(0.4e-3, fresh);
  EXPECT_TRUE(a.rgb == b.rgb) << "same renderer, same instant";
  EXPECT_TRUE(a.rgb == fresh.rgb) << "new context, same instant";
  EXPECT_FALSE(a.rgb == c.rgb) << "a different instant must differ";

  const auto dir = std::filesystem::temp_directory_path() / "railjoint_render_identical";
  std::filesystem::create_directories(dir);
  write_png(dir / "a.png", a);
  write_png(dir / "b.png", fresh);
  auto bytes = [](const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::vector<char>(std::istreambuf_iterator<char>(in), {});
  };
  const auto pa = bytes(dir / "a.png"), pb = bytes(dir / "b.png");
  std::cout << "PNG size " << pa.size() << " bytes\n";
  EXPECT_GT(pa.size(), 100u);
  EXPECT_TRUE(pa == pb);
}

TEST(CrossingRender, SpinTurnsTheMarkerForwardAboutTheAxle) {
  // Rolling forward (+x) turns the wheel about +y: the front of the wheel
  // goes down. The knob sits on the +x end of the bar at spin 0, so the dark
  // marker's centroid is right of the centre at spin 0 and below it at spin pi/2.
  const Scene scene;
  const Trajectory t = rolling(-0.25, -0.15, 0.0, std::numbers::pi);
  CrossingRenderer renderer(test_settings(), scene.rails, scene.wheel, t);
  RgbImage at_zero, at_quarter;
  renderer.render_at(0.0, at_zero);
  renderer.render_at(0.5e-3, at_quarter);  // spin interpolated to pi/2

  const Centroid w0 = centroid(at_zero, is_wheel), s0 = centroid(at_zero, is_spoke);
  const Centroid w1 = centroid(at_quarter, is_wheel), s1 = centroid(at_quarter, is_spoke);
  std::cout << "spin 0: marker - wheel = (" << s0.u - w0.u << ", " << s0.v - w0.v << ") px; spin pi/2: ("
            << s1.u - w1.u << ", " << s1.v - w1.v << ") px\n";
  // The knob adds about 0.035 R^2 at 0.675 R to a bar of 0.18 R^2 at 0:
  // an offset of ~0.11 R = 14 px; ask for more than 5 px in the right
  // direction and less than 1.5 px across it.
  EXPECT_GT(s0.u - w0.u, 5.0);
  EXPECT_NEAR(s0.v - w0.v, 0.0, 1.5);
  EXPECT_GT(s1.v - w1.v, 5.0);  // image v grows downwards
  EXPECT_NEAR(s1.u - w1.u, 0.0, 1.5);
}

TEST(CrossingRender, ImpactFramesAreMarkedAndOthersAreNot) {
  const Scene scene;
  Trajectory t = rolling(-0.25, -0.15);
  ImpactEvent impact;
  impact.time_s = 0.5e-3;
  impact.wheel_x_m = -0.2;
  impact.momentum_jump_Ns = 123.4;
  impact.contact_point_m = {-0.2, kYw, kTanHalfBeta * 0.2};
  t.impacts.push_back(impact);
  CrossingRenderer renderer(test_settings(), scene.rails, scene.wheel, t);  // 10000 fps: frames 0.1 ms apart
  RgbImage at_impact, one_frame_after, far_away;
  renderer.render_at(0.5e-3, at_impact);
  renderer.render_at(0.6e-3, one_frame_after);
  renderer.render_at(0.9e-3, far_away);
  auto orange = [](const RgbImage& image) { return centroid(image, is_impact_orange).count; };
  std::cout << "impact-orange pixels: at impact " << orange(at_impact) << ", one frame after "
            << orange(one_frame_after) << ", 4 frames after " << orange(far_away) << "\n";
  // The border alone is 2 * 6 px * (640 + 480) px ~ 13,000 px.
  EXPECT_GT(orange(at_impact), 10000);
  EXPECT_GT(orange(one_frame_after), 10000);  // within one frame period
  EXPECT_EQ(orange(far_away), 0);

  // The big marker sits at the drawn contact point (x, k z) = (-0.2, 20 * 0.003)
  // m, on top of everything: u = 320 (the camera is centred on x = -0.2),
  // v = pixel_v(0.06) = 319. Count only orange inside the border and below
  // the label lines (the label is orange too).
  Centroid marker;
  for (int row = 60; row < kH - 12; ++row)
    for (int col = 12; col < kW - 12; ++col) {
      if (!is_impact_orange(at_impact.pixel(col, row))) continue;
      marker.u += col + 0.5;
      marker.v += row + 0.5;
      ++marker.count;
    }
  ASSERT_GT(marker.count, 0);
  marker.u /= static_cast<double>(marker.count);
  marker.v /= static_cast<double>(marker.count);
  const double u = pixel_u(-0.2, -0.2), v = pixel_v(kK * kTanHalfBeta * 0.2);
  std::cout << "impact marker centroid (" << marker.u << ", " << marker.v << ") from " << marker.count
            << " px; projection (" << u << ", " << v << ")\n";
  // A round marker is symmetric about its centre: 1 px for rasterisation.
  EXPECT_NEAR(marker.u, u, 1.0);
  EXPECT_NEAR(marker.v, v, 1.0);
}

TEST(CrossingRender, TopViewPutsTheWheelAtItsLateralPosition) {
  // Top view, automatic framing: visible height = 3 rail widths = 0.12 m over
  // 480 px (4000 px/m), centred on y = 0, image up = +y. The wheel band
  // (y_w +- 5 mm, the mesh's minimum width) is centred at v = 240 - 0.015 * 4000 = 180.
  const Scene scene;
  RenderSettings s = test_settings();
  s.view = RenderView::top;
  s.view_width_m.reset();
  s.follow_wheel = true;
  CrossingRenderer renderer(s, scene.rails, scene.wheel, rolling(-0.25, -0.15));
  RgbImage image;
  renderer.render_at(0.5e-3, image);
  const Centroid wheel = centroid(image, is_wheel);
  std::cout << "top view wheel centroid (" << wheel.u << ", " << wheel.v << ") from " << wheel.count << " px\n";
  // The band runs across the whole image (2R = 0.95 m >> 0.16 m visible): 640 x 40 px.
  EXPECT_NEAR(static_cast<double>(wheel.count), 640.0 * 40.0, 640.0 * 2.0);
  EXPECT_NEAR(wheel.v, 180.0, 1.0);
  EXPECT_NEAR(wheel.u, 320.0, 1.0);  // following: the band is centred across
}

TEST(CrossingRender, PerspectiveViewShowsWheelAndRails) {
  const Scene scene;
  RenderSettings s = test_settings();
  s.view = RenderView::perspective;
  s.follow_wheel = true;
  CrossingRenderer renderer(s, scene.rails, scene.wheel, rolling(-0.25, -0.15));
  RgbImage image;
  renderer.render_at(0.5e-3, image);
  const Centroid wheel = centroid(image, is_wheel);
  long long rail_top = 0;  // palette::rail_top is a gold: red and green well above blue
  for (int row = 0; row < kH; ++row)
    for (int col = 0; col < kW; ++col) {
      const auto* p = image.pixel(col, row);
      rail_top += (p[0] > p[2] + 60 && p[1] > p[2] + 40) ? 1 : 0;
    }
  std::cout << "perspective: wheel " << wheel.count << " px at (" << wheel.u << ", " << wheel.v << "), rail top "
            << rail_top << " px\n";
  // The camera looks at the wheel: it fills a good part of the middle of the picture.
  EXPECT_GT(wheel.count, kW * kH / 10);
  EXPECT_NEAR(wheel.u, kW / 2.0, kW / 4.0);
  EXPECT_GT(rail_top, 500);
}

}  // namespace
}  // namespace railjoint
