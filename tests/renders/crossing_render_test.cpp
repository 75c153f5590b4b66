// Pixels of rendered frames against where the camera conventions
// (renders/camera.h) and the one affine exaggeration map put things. Needs OSMesa.
//
// Contact view (the defaults): 1280 x 720 px, side view, visible width
// W = 0.12 m -> s = 10,666.7 px/m both ways; exaggeration k = 20 about
// z_ref = 0; the camera follows the wheel and is centred on its drawn lowest
// point F = (x_c, k (z_c - R)). A world point (x, z), drawn at z' = k z, lands at
//   u = 640 + (x - x_c) s,   v = 360 - (z' - k (z_c - R)) s
// (u right, v down from the top-left corner; pixel (i, j) covers
// [i, i+1) x [j, j+1) and is drawn when its centre (i + 0.5, j + 0.5) is inside
// a shape, so a boundary at v is seen as the first covered row ceil(v - 0.5)).
//
// Joint: the thesis's default (theta 30 deg, beta 0.03 rad, b_t 20 mm,
// L = 1 m, depth 50 mm): incoming rail top z = -t x up to the cut
// x = y cot(theta), outgoing rail top z = +t x beyond it, t = tan(beta/2).
// Wheel: R = 0.475 m, 1 mm wide at y_w = 15 mm (the simulation's stand-in for
// a thin disc), so the side view's section through it spans y = 14.5 .. 15.5 mm.

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <limits>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "geometry/rail_joint_mesh.h"
#include "geometry/wheel_mesh.h"
#include "models/impact_prediction.h"
#include "renders/crossing_renderer.h"
#include "renders/png_file.h"
#include "renders/wheel_tessellation.h"

namespace railjoint {
namespace {

constexpr double kR = 0.475;
constexpr double kYw = 0.015;
constexpr double kWheelWidth = 0.001;
constexpr double kK = 20.0;
const double kT = std::tan(0.015);  // tan(beta/2)

RenderSettings contact_view() {
  RenderSettings s;  // 1280 x 720, side, k = 20, W = 0.12 m, follow
  s.fps = 10000;
  s.ffmpeg = false;
  return s;
}

struct View {
  double width = 1280, height = 720, px_per_m = 1280 / 0.12, k = kK;
  Eigen::Vector3d centre;  // wheel centre, real coordinates
  double u(double x) const { return width / 2 + (x - centre.x()) * px_per_m; }
  double v(double z) const { return height / 2 - (k * z - k * (centre.z() - kR)) * px_per_m; }
  double x_of_column(int col) const { return centre.x() + (col + 0.5 - width / 2) / px_per_m; }
};

WheelParams test_wheel() {
  WheelParams w;
  w.width_m = kWheelWidth;
  w.lateral_m = kYw;
  return w;
}

TriangleMesh fine_wheel(const RenderSettings& s) { return build_wheel_mesh(test_wheel(), wheel_render_segments(s, kR), 0.0); }

WheelSample at(double t, const Eigen::Vector3d& centre, double spin = 0.0) {
  WheelSample s;
  s.time_s = t;
  s.centre_m = centre;
  s.velocity_m_per_s = {50.0, 0.0, 0.0};
  s.spin_angle_rad = spin;
  return s;
}

// A wheel resting on the incoming slope z = -t x touches it at the foot of the
// normal through its centre: c = p + R (t, 0, 1) / sqrt(1 + t^2), so
// z_c = -t x_c + R sqrt(1 + t^2), and the contact lies R sin(beta/2) behind x_c.
Eigen::Vector3d resting_on_incoming(double x) { return {x, kYw, -kT * x + kR * std::sqrt(1.0 + kT * kT)}; }

// Pixel classes by hue (renders/palette.h): the wheel is the only thing drawn
// in clear blues; the background is one flat colour; rails are neither.
bool is_wheel(const std::uint8_t* p) { return p[2] >= p[0] + 40 && p[2] >= p[1] + 40; }
bool is_spoke(const std::uint8_t* p) { return is_wheel(p) && p[2] < 140; }  // the dark bar, knob and ticks
bool is_background(const std::uint8_t* p) {
  // palette::background (0.93, 0.95, 0.98) as 8 bits.
  return std::abs(p[0] - 237) <= 1 && std::abs(p[1] - 242) <= 1 && std::abs(p[2] - 250) <= 1;
}
bool is_impact_orange(const std::uint8_t* p) { return p[0] > 230 && p[1] > 90 && p[1] < 140 && p[2] < 30; }

// In one column: the last row of the wheel's lower outline (the last wheel
// pixel with a non-wheel pixel below it, searched from row `from` down) and
// the first rail pixel below it. -1 when not found.
struct ColumnScan {
  int wheel_bottom = -1;
  int rail_top = -1;
};
ColumnScan scan(const RgbImage& image, int col, int from) {
  ColumnScan c;
  for (int row = from; row < image.height_px; ++row) {
    if (is_wheel(image.pixel(col, row))) c.wheel_bottom = row;
    else if (c.wheel_bottom >= 0) break;
  }
  // Rail: three solid rows, so the 1 px datum line (behind everything, seen in gaps) is not taken for it.
  auto solid = [&](int row) {
    const auto* p = image.pixel(col, row);
    return !is_wheel(p) && !is_background(p);
  };
  for (int row = std::max(from, c.wheel_bottom + 1); row + 2 < image.height_px; ++row) {
    if (solid(row) && solid(row + 1) && solid(row + 2)) {
      c.rail_top = row;
      break;
    }
  }
  return c;
}

double first_row(double v) { return std::ceil(v - 0.5); }  // first pixel row whose centre lies below v

TEST(CrossingRender, ContextReportsItsGlVersion) {
  const RenderSettings s = contact_view();
  const Trajectory t{{at(0.0, resting_on_incoming(-0.2)), at(1e-4, resting_on_incoming(-0.195))}, {}};
  CrossingRenderer renderer(s, build_rail_joint_mesh(JointParams{}), build_wheel_mesh(test_wheel(), 64, 0.0), t);
  std::cout << "GL_VERSION " << renderer.gl_version() << ", GL_RENDERER " << renderer.gl_renderer() << "\n";
  RecordProperty("gl_version", renderer.gl_version());
  // We asked for a 3.3 core profile; Mesa gives the newest it has (4.5 here).
  ASSERT_GE(renderer.gl_version().size(), 3u);
  EXPECT_GE(renderer.gl_version()[0], '3');
}

// The wheel resting on the incoming slope at x_c = -0.2 m, clear of the cut.
// Drawn with the same map as the rails, its outline is the ellipse
//   z'(x) = k (z_c - sqrt(R^2 - (x - x_c)^2)),
// rising k (x - x_c)^2 / (2 R) above its lowest point: 79 px at 200 px to
// either side (a rigid circle would rise 4 px), and it touches the drawn
// slope z' = -k t x exactly at the drawn contact, R sin(beta/2) behind x_c.
TEST(CrossingRender, WheelIsTheMappedEllipseTouchingTheMappedSlopeAtTheContact) {
  const RenderSettings s = contact_view();
  View view;
  view.centre = resting_on_incoming(-0.2);
  const Trajectory t{{at(0.0, view.centre), at(1e-4, resting_on_incoming(-0.195))}, {}};
  CrossingRenderer renderer(s, build_rail_joint_mesh(JointParams{}), fine_wheel(s), t);
  RgbImage image;
  renderer.render_at(0.0, image);

  for (int du : {-200, -100, -30, 0, 30, 100, 200}) {
    const int col = 640 + du;
    const double x = view.x_of_column(col);
    const double dx = x - view.centre.x();
    const double v_wheel = view.v(view.centre.z() - std::sqrt(kR * kR - dx * dx));
    const double v_rail = view.v(-kT * x);
    const ColumnScan c = scan(image, col, 150);  // below the label box
    std::cout << "column " << col << ": wheel outline ends at row " << c.wheel_bottom << " (ellipse: first row below "
              << first_row(v_wheel) << "), rail from row " << c.rail_top << " (slope: " << first_row(v_rail) << ")\n";
    // 1 px: rasterisation of the 1,415-sided polygon (its facets lie within
    // 0.25 px of the ellipse) and of the rail's edge.
    EXPECT_NEAR(c.wheel_bottom + 1, first_row(v_wheel), 1.0) << "column " << col;
    EXPECT_NEAR(c.rail_top, first_row(v_rail), 1.0) << "column " << col;
  }

  // Tangency at the drawn contact p = c - R (t, 0, 1) / sqrt(1 + t^2): no background between.
  const Eigen::Vector3d p = view.centre - kR * Eigen::Vector3d(kT, 0.0, 1.0) / std::sqrt(1.0 + kT * kT);
  const int col_p = static_cast<int>(std::floor(view.u(p.x())));
  const ColumnScan c = scan(image, col_p, 150);
  std::cout << "contact column " << col_p << ": wheel to row " << c.wheel_bottom << ", rail from row " << c.rail_top
            << ", drawn contact at v = " << view.v(p.z()) << "\n";
  EXPECT_LE(c.rail_top - (c.wheel_bottom + 1), 1) << "a gap between wheel and rail at the contact";
  EXPECT_NEAR(c.rail_top, view.v(p.z()), 1.5);
}

// The scenario-2 impact of the 1 mm wheel (its inner face, y1 = 14.5 mm,
// governs): the wheel centre and the contacts A (on the outgoing rail's
// corner at the cut, x_A = y1 cot(theta)) and B (on the incoming slope) from
// the analytic model. In the section y1 .. y2 the rails' outline is
//   z = -t x for x < x1 = y1 cot(theta) (incoming rail), z = +t x beyond,
// with the step of 2 t x1 at x1. The drawn wheel must touch this outline at
// the drawn A and B and stay out of the rails everywhere else.
TEST(CrossingRender, AtTheImpactTheWheelTouchesAAndBAndCutsIntoNothing) {
  const JointParams joint;
  const ImpactPrediction impact = predict_impact(joint, test_wheel());
  const RenderSettings s = contact_view();
  View view;
  view.centre = Eigen::Vector3d(impact.impact_wheel_x_m, kYw, impact.impact_wheel_z_m);
  const double cot = 1.0 / std::tan(joint.theta_rad);
  const double x1 = (kYw - kWheelWidth / 2) * cot;
  std::cout << "governing y " << impact.governing_y_m * 1e3 << " mm, centre (" << view.centre.x() * 1e3 << ", "
            << view.centre.z() * 1e3 << ") mm, A (" << impact.contact_A_m.x() * 1e3 << ", "
            << impact.contact_A_m.z() * 1e3 << ") mm, B (" << impact.contact_B_m.x() * 1e3 << ", "
            << impact.contact_B_m.z() * 1e3 << ") mm, corner x1 = " << x1 * 1e3 << " mm\n";
  ASSERT_NEAR(impact.contact_A_m.x(), x1, 1e-9);  // the hand derivation and the model agree on the corner

  const Trajectory t{{at(0.0, view.centre), at(1e-4, view.centre)}, {}};
  CrossingRenderer renderer(s, build_rail_joint_mesh(joint), fine_wheel(s), t);
  RgbImage image;
  renderer.render_at(0.0, image);
  auto outline = [&](double x) { return x < x1 ? -kT * x : kT * x; };

  // No wheel pixel inside the rails: depth of every wheel pixel centre below the outline.
  double deepest_px = -std::numeric_limits<double>::infinity();
  long long wheel_pixels = 0, inside = 0;
  for (int col = 0; col < image.width_px; ++col) {
    const double v_rail = view.v(outline(view.x_of_column(col)));
    for (int row = 0; row < image.height_px; ++row) {
      if (!is_wheel(image.pixel(col, row))) continue;
      ++wheel_pixels;
      const double depth = row + 0.5 - v_rail;
      deepest_px = std::max(deepest_px, depth);
      inside += depth > 1.5 ? 1 : 0;
    }
  }
  std::cout << wheel_pixels << " wheel pixels; deepest below the rails' outline: " << deepest_px << " px; "
            << inside << " deeper than 1.5 px\n";
  EXPECT_GT(wheel_pixels, 100000);
  // A pixel is drawn when its centre is inside the wheel, which never enters
  // the rails: its centre can lie at most 0.5 px past the rails' edge within
  // the edge pixel; 1.5 px allows for the polygon and for rounding.
  EXPECT_EQ(inside, 0);
  EXPECT_LT(deepest_px, 1.5);

  // The lowest point of the ellipse at the image centre: first free row 360.
  int lowest = -1;
  for (int col = 600; col < 680; ++col) lowest = std::max(lowest, scan(image, col, 150).wheel_bottom);
  std::cout << "lowest wheel row near the centre column: " << lowest << "\n";
  EXPECT_NEAR(lowest + 1, 360, 1.0);

  // Touching at B and at A: the wheel's outline meets the rails' outline at the drawn points.
  const int col_b = static_cast<int>(std::floor(view.u(impact.contact_B_m.x())));
  const ColumnScan b = scan(image, col_b, 150);
  const int col_a = static_cast<int>(std::floor(view.u(x1))) + 1;  // first column past the corner
  const ColumnScan a = scan(image, col_a, 150);
  std::cout << "B: column " << col_b << ", wheel to row " << b.wheel_bottom << ", rail from row " << b.rail_top
            << ", drawn B at v = " << view.v(impact.contact_B_m.z()) << "\n"
            << "A: column " << col_a << ", wheel to row " << a.wheel_bottom << ", rail from row " << a.rail_top
            << ", drawn A at v = " << view.v(impact.contact_A_m.z()) << "\n";
  // 1.5 px: rasterisation of both edges at the point where they meet.
  EXPECT_NEAR(b.wheel_bottom + 1, view.v(impact.contact_B_m.z()), 1.5);
  EXPECT_NEAR(b.rail_top, view.v(impact.contact_B_m.z()), 1.5);
  EXPECT_NEAR(a.wheel_bottom + 1, view.v(impact.contact_A_m.z()), 1.5);
  EXPECT_NEAR(a.rail_top, view.v(impact.contact_A_m.z()), 1.5);
  // And the step at the cut is there: left of the corner the rail top lies
  // 2 t x1 lower (0.78 mm, drawn 15.6 mm = 166 px).
  const ColumnScan below = scan(image, col_a - 3, 150);
  std::cout << "left of the corner the rail starts at row " << below.rail_top << "\n";
  EXPECT_NEAR(below.rail_top - a.rail_top, 2.0 * kT * x1 * kK * view.px_per_m, 3.0);
}

TEST(CrossingRender, SameInputGivesByteIdenticalImagesAndFiles) {
  RenderSettings s = contact_view();
  s.width_px = 640;
  s.height_px = 360;
  const Trajectory t{{at(0.0, resting_on_incoming(-0.2), 0.0), at(1e-3, resting_on_incoming(-0.15), 0.3)}, {}};
  const RailJointMesh rails = build_rail_joint_mesh(JointParams{});
  const TriangleMesh wheel = fine_wheel(s);
  RgbImage a, b, c;
  {
    CrossingRenderer renderer(s, rails, wheel, t);
    renderer.render_at(0.4e-3, a);
    renderer.render_at(0.9e-3, c);  // something else in between
    renderer.render_at(0.4e-3, b);
  }
  RgbImage fresh;  // a second context
  CrossingRenderer other(s, rails, wheel, t);
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
  // Whole wheel, no exaggeration: 640 x 480 px over 3.2 m (200 px/m), the
  // lowest point at the image centre, so the wheel centre is R s = 95 px
  // above it, at (320, 145). Rolling forward (+x) turns the wheel about +y:
  // the front goes down. The knob sits on the +x end of the bar at spin 0,
  // so the dark marker's centroid is right of the centre at spin 0 and below
  // it at spin pi/2. Only pixels within 0.7 R of the centre count (the rim
  // ticks lie beyond 0.75 R and are spread evenly around the rim anyway).
  RenderSettings s = contact_view();
  s.width_px = 640;
  s.height_px = 480;
  s.exaggeration = 1.0;
  s.view_width_m = 3.2;
  const Trajectory t{{at(0.0, resting_on_incoming(-0.25), 0.0), at(1e-3, resting_on_incoming(-0.15), std::numbers::pi)}, {}};
  CrossingRenderer renderer(s, build_rail_joint_mesh(JointParams{}), build_wheel_mesh(test_wheel(), 128, 0.0), t);
  auto marker_offset = [&](double time) {
    RgbImage image;
    renderer.render_at(time, image);
    const double uc = 320.0, vc = 240.0 - kR * 200.0, r_max = 0.7 * kR * 200.0;
    double su = 0, sv = 0;
    long long n = 0;
    for (int row = 0; row < image.height_px; ++row)
      for (int col = 0; col < image.width_px; ++col) {
        const double du = col + 0.5 - uc, dv = row + 0.5 - vc;
        if (du * du + dv * dv > r_max * r_max || !is_spoke(image.pixel(col, row))) continue;
        su += du;
        sv += dv;
        ++n;
      }
    return Eigen::Vector2d(su / static_cast<double>(n), sv / static_cast<double>(n));
  };
  const Eigen::Vector2d zero = marker_offset(0.0), quarter = marker_offset(0.5e-3);  // spin interpolated to pi/2
  std::cout << "spin 0: marker - centre = (" << zero.transpose() << ") px; spin pi/2: (" << quarter.transpose()
            << ") px\n";
  // Inside 0.7 R the bar covers 2 * 0.7 R * 0.1 R = 0.14 R^2, the knob adds
  // 0.15 R * 0.14 R = 0.021 R^2 at 0.625 R: an offset of 0.08 R = 7.7 px.
  // Ask for more than 4 px in the right direction and less than 1.5 px across it.
  EXPECT_GT(zero.x(), 4.0);
  EXPECT_NEAR(zero.y(), 0.0, 1.5);
  EXPECT_GT(quarter.y(), 4.0);  // image v grows downwards
  EXPECT_NEAR(quarter.x(), 0.0, 1.5);
}

TEST(CrossingRender, ImpactFramesAreMarkedAndOthersAreNot) {
  // 640 x 360 px over 0.12 m: 5,333 px/m. The scenario-2 impact state, the
  // impact recorded at t = 0 with the contact point A.
  const JointParams joint;
  const ImpactPrediction prediction = predict_impact(joint, test_wheel());
  RenderSettings s = contact_view();  // 10000 fps: frames 0.1 ms apart
  s.width_px = 640;
  s.height_px = 360;
  View view;
  view.width = 640;
  view.height = 360;
  view.px_per_m = 640 / 0.12;
  view.centre = Eigen::Vector3d(prediction.impact_wheel_x_m, kYw, prediction.impact_wheel_z_m);
  Trajectory t{{at(0.0, view.centre), at(5e-4, view.centre)}, {}};
  ImpactEvent impact;
  impact.time_s = 0.0;
  impact.wheel_x_m = view.centre.x();
  impact.momentum_jump_Ns = 123.4;
  impact.contact_point_m = prediction.contact_A_m;
  t.impacts.push_back(impact);
  CrossingRenderer renderer(s, build_rail_joint_mesh(joint), fine_wheel(s), t);
  RgbImage at_impact, one_frame_after, far_away;
  renderer.render_at(0.0, at_impact);
  renderer.render_at(1e-4, one_frame_after);
  renderer.render_at(4e-4, far_away);
  auto orange = [](const RgbImage& image) {
    long long n = 0;
    for (int row = 0; row < image.height_px; ++row)
      for (int col = 0; col < image.width_px; ++col) n += is_impact_orange(image.pixel(col, row)) ? 1 : 0;
    return n;
  };
  std::cout << "impact-orange pixels: at impact " << orange(at_impact) << ", one frame after "
            << orange(one_frame_after) << ", 4 frames after " << orange(far_away) << "\n";
  // The border alone is 4 px wide: 2 * 4 * (640 + 352) = 7,936 px.
  EXPECT_GT(orange(at_impact), 7000);
  EXPECT_GT(orange(one_frame_after), 7000);  // within one frame period
  EXPECT_EQ(orange(far_away), 0);

  // The ring sits at the drawn A, on top of everything: count orange within 40 px of it.
  const double u = view.u(prediction.contact_A_m.x()), v = view.v(prediction.contact_A_m.z());
  double su = 0, sv = 0;
  long long n = 0;
  for (int row = static_cast<int>(v) - 40; row < static_cast<int>(v) + 40; ++row)
    for (int col = static_cast<int>(u) - 40; col < static_cast<int>(u) + 40; ++col) {
      if (!is_impact_orange(at_impact.pixel(col, row))) continue;
      su += col + 0.5;
      sv += row + 0.5;
      ++n;
    }
  ASSERT_GT(n, 0);
  std::cout << "impact ring centroid (" << su / n << ", " << sv / n << ") from " << n << " px; drawn A (" << u << ", "
            << v << ")\n";
  // A ring is symmetric about its centre: 1 px for rasterisation.
  EXPECT_NEAR(su / n, u, 1.0);
  EXPECT_NEAR(sv / n, v, 1.0);
}

TEST(CrossingRender, TopViewPutsTheWheelAtItsLateralPosition) {
  // Top view, automatic framing: visible height = 3 rail widths = 0.12 m over
  // 480 px (4000 px/m), centred on y = 0, image up = +y. A 10 mm wide wheel
  // band (y_w +- 5 mm) is centred at v = 240 - 0.015 * 4000 = 180, 40 px tall.
  RenderSettings s = contact_view();
  s.width_px = 640;
  s.height_px = 480;
  s.view = RenderView::top;
  WheelParams wide = test_wheel();
  wide.width_m = 0.01;
  const Trajectory t{{at(0.0, resting_on_incoming(-0.25)), at(1e-3, resting_on_incoming(-0.15))}, {}};
  CrossingRenderer renderer(s, build_rail_joint_mesh(JointParams{}), build_wheel_mesh(wide, 256, 0.0), t);
  RgbImage image;
  renderer.render_at(0.5e-3, image);
  double su = 0, sv = 0;
  long long n = 0;
  for (int row = 0; row < image.height_px; ++row)
    for (int col = 0; col < image.width_px; ++col) {
      if (!is_wheel(image.pixel(col, row))) continue;
      su += col + 0.5;
      sv += row + 0.5;
      ++n;
    }
  std::cout << "top view wheel centroid (" << su / n << ", " << sv / n << ") from " << n << " px\n";
  // The band runs across the whole image (2R = 0.95 m >> 0.16 m visible): 640 x 40 px.
  EXPECT_NEAR(static_cast<double>(n), 640.0 * 40.0, 640.0 * 2.0);
  EXPECT_NEAR(sv / n, 180.0, 1.0);
  EXPECT_NEAR(su / n, 320.0, 1.0);  // following: the band is centred across
}

TEST(CrossingRender, PerspectiveViewShowsWheelAndRails) {
  RenderSettings s = contact_view();
  s.width_px = 640;
  s.height_px = 480;
  s.view = RenderView::perspective;
  const Trajectory t{{at(0.0, resting_on_incoming(-0.25)), at(1e-3, resting_on_incoming(-0.15))}, {}};
  CrossingRenderer renderer(s, build_rail_joint_mesh(JointParams{}), fine_wheel(s), t);
  RgbImage image;
  renderer.render_at(0.5e-3, image);
  long long wheel = 0, rail_top = 0;  // palette::rail_top is a gold: red and green well above blue
  double wheel_u = 0;
  for (int row = 0; row < image.height_px; ++row)
    for (int col = 0; col < image.width_px; ++col) {
      const auto* p = image.pixel(col, row);
      if (is_wheel(p)) {
        ++wheel;
        wheel_u += col + 0.5;
      }
      rail_top += (p[0] > p[2] + 60 && p[1] > p[2] + 40) ? 1 : 0;
    }
  std::cout << "perspective: wheel " << wheel << " px at u = " << wheel_u / wheel << ", rail top " << rail_top
            << " px\n";
  // The camera looks at the wheel's lowest point, so that point projects to
  // the image centre (320, 240): in the centre column the wheel ends there
  // (its lowest wheel-coloured pixel; rows counted from the top, the outline
  // drawn over the silhouette's edge allows a few pixels).
  int lowest_wheel_row = -1;
  for (int row = 0; row < image.height_px; ++row) {
    if (is_wheel(image.pixel(320, row))) lowest_wheel_row = row;
  }
  std::cout << "lowest wheel pixel in column 320: row " << lowest_wheel_row << "\n";
  EXPECT_NEAR(lowest_wheel_row, 240, 4);
  // The wheel fills a good part of the picture above it.
  EXPECT_GT(wheel, 640 * 480 / 10);
  EXPECT_NEAR(wheel_u / wheel, 320.0, 160.0);
  EXPECT_GT(rail_top, 500);
}

}  // namespace
}  // namespace railjoint
