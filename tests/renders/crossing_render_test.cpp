// Pixels of rendered frames against where the camera conventions
// (renders/camera.h) and the one affine exaggeration map put things. Needs a GL back end.
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
#include <memory>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <limits>
#include <optional>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/scratch_dir.h"
#include "geometry/rail_joint_mesh.h"
#include "geometry/wheel_mesh.h"
#include "models/impact_prediction.h"
#include "renders/crossing_view.h"
#include "renders/perspective_view.h"
#include "renders/top_view.h"
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
// in clear blues; rails are not.
bool is_wheel(const std::uint8_t* p) { return p[2] >= p[0] + 40 && p[2] >= p[1] + 40; }
bool is_spoke(const std::uint8_t* p) { return is_wheel(p) && p[2] < 140; }  // the dark bar, knob and ticks
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
  // Frames are anti-aliased (4 samples a pixel): an edge pixel is a blend, so
  // a pixel counts as rail when it is at least half covered: darker than the
  // mean of the background (RGB sum 729) and the lighter rail section face
  // (palette::rail_side lit by 0.30 + 0.45 n.l + 0.25 = 0.908 facing the
  // viewer: (139, 132, 123), sum 394), i.e. an RGB sum below 561.
  auto solid = [&](int row) {
    const auto* p = image.pixel(col, row);
    return !is_wheel(p) && p[0] + p[1] + p[2] < 561;
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
  const auto renderer = CrossingView::make(s, build_rail_joint_mesh(JointParams{}), build_wheel_mesh(test_wheel(), 64, 0.0), t);
  std::cout << "GL_VERSION " << renderer->gl_version() << ", GL_RENDERER " << renderer->gl_renderer() << "\n";
  RecordProperty("gl_version", renderer->gl_version());
  // We asked for a 3.3 core profile; Mesa gives the newest it has (4.5 here).
  ASSERT_GE(renderer->gl_version().size(), 3u);
  EXPECT_GE(renderer->gl_version()[0], '3');
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
  const auto renderer = CrossingView::make(s, build_rail_joint_mesh(JointParams{}), fine_wheel(s), t);
  RgbImage image;
  renderer->render_at(0.0, image);

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
  const auto renderer = CrossingView::make(s, build_rail_joint_mesh(joint), fine_wheel(s), t);
  RgbImage image;
  renderer->render_at(0.0, image);
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
    const auto renderer = CrossingView::make(s, rails, wheel, t);
    renderer->render_at(0.4e-3, a);
    renderer->render_at(0.9e-3, c);  // something else in between
    renderer->render_at(0.4e-3, b);
  }
  RgbImage fresh;  // a second context
  const auto other = CrossingView::make(s, rails, wheel, t);
  other->render_at(0.4e-3, fresh);
  EXPECT_TRUE(a.rgb == b.rgb) << "same renderer, same instant";
  EXPECT_TRUE(a.rgb == fresh.rgb) << "new context, same instant";
  EXPECT_FALSE(a.rgb == c.rgb) << "a different instant must differ";

  const auto dir = testing_support::scratch_dir();
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
  const auto renderer = CrossingView::make(s, build_rail_joint_mesh(JointParams{}), build_wheel_mesh(test_wheel(), 128, 0.0), t);
  auto marker_offset = [&](double time) {
    RgbImage image;
    renderer->render_at(time, image);
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
  const auto renderer = CrossingView::make(s, build_rail_joint_mesh(joint), fine_wheel(s), t);
  RgbImage at_impact, one_frame_after, far_away;
  renderer->render_at(0.0, at_impact);
  renderer->render_at(1e-4, one_frame_after);
  renderer->render_at(4e-4, far_away);
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

// A wheel resting on the incoming slope, with its contact point recorded as
// the simulation records it (on the rail, R sin(beta/2) behind the centre).
WheelSample resting_with_contact(double t, double x) {
  WheelSample s = at(t, resting_on_incoming(x));
  ContactSample c;
  c.point_on_rail_m = s.centre_m - kR * Eigen::Vector3d(kT, 0.0, 1.0) / std::sqrt(1.0 + kT * kT);
  c.distance_m = 0.0;
  s.contacts.push_back(c);
  return s;
}

int rgb_sum(const std::uint8_t* p) { return p[0] + p[1] + p[2]; }

TEST(CrossingRender, TopViewShowsTheRunningBandUnderTheSeeThroughWheelUpToTheContact) {
  // Top view, automatic framing: visible height = 3 rail widths = 0.12 m over
  // 480 px (4000 px/m), centred on y = 0, image up = +y, following the
  // wheel's lowest point. A 10 mm wide wheel at y_w = 15 mm rolls from
  // x = -0.25 m to -0.15 m; its running band covers y = 10 .. 20 mm (the
  // rail head ends at b_t = 20 mm): rows 240 - 0.020 * 4000 = 160 to
  // 240 - 0.010 * 4000 = 200. Along x it reaches the current contact,
  // R sin(beta/2) = 7.1 mm behind the centre: column 320 - 0.00712 * 4000 = 291.5.
  RenderSettings s = contact_view();
  s.width_px = 640;
  s.height_px = 480;
  s.view = RenderView::top;
  WheelParams wide = test_wheel();
  wide.width_m = 0.01;
  Trajectory t;
  for (int i = 0; i <= 10; ++i) t.samples.push_back(resting_with_contact(i * 1e-4, -0.25 + 0.01 * i));
  const auto renderer = CrossingView::make(s, build_rail_joint_mesh(JointParams{}), build_wheel_mesh(wide, 256, 0.0), t);
  RgbImage image;
  renderer->render_at(0.5e-3, image);
  const double contact_u = 320.0 - kR * kT / std::sqrt(1.0 + kT * kT) * 4000.0;

  // Row 170 (y = 17.5 mm, clear of the contact marker on row 180): dark band
  // from the first contact (x = -0.257 m, column 92) up to the current one,
  // the lighter rail head beyond.
  const int far_left = rgb_sum(image.pixel(200, 170)), far_right = rgb_sum(image.pixel(620, 170));
  const int middle = (far_left + far_right) / 2;
  int end_column = -1;
  for (int col = 200; col < image.width_px; ++col) {
    if (rgb_sum(image.pixel(col, 170)) > middle) {
      end_column = col;
      break;
    }
  }
  std::cout << "row 170: RGB sum " << far_left << " (band) to " << far_right << " (rail); band ends at column "
            << end_column << ", contact at u = " << contact_u << "\n";
  // palette::running_band is less than half as bright as palette::rail_top;
  // under the 35 % opaque wheel the sums measured 200 against 288.
  EXPECT_LT(far_left + 50, far_right) << "the band must be clearly darker than the rail head";
  // 1.5 px: the band's end is the recorded contact's x; a pixel is counted by its centre.
  EXPECT_NEAR(end_column, contact_u, 1.5);

  // Column 200, behind the contact: the band's rows (searched over the rail
  // head and the ground beside it, above the label box).
  long long rows = 0;
  double row_sum = 0.0;
  for (int row = 80; row < 400; ++row) {
    if (rgb_sum(image.pixel(200, row)) < middle) {
      ++rows;
      row_sum += row + 0.5;
    }
  }
  std::cout << "column 200: " << rows << " band rows centred on row " << row_sum / rows << "\n";
  // 40 rows (10 mm at 4000 px/m), centred at row 180; 2 px for the edges' blend.
  EXPECT_NEAR(static_cast<double>(rows), 40.0, 2.0);
  EXPECT_NEAR(row_sum / rows, 180.0, 1.0);

  // The see-through wheel tints what lies under it blue: at y = 15 mm (under
  // the wheel) blue minus red is larger than at y = 5 mm (row 220, bare rail head).
  auto blue_excess = [&](int col, int row) { return image.pixel(col, row)[2] - image.pixel(col, row)[0]; };
  std::cout << "blue - red at column 500: row 180 " << blue_excess(500, 180) << ", row 220 " << blue_excess(500, 220)
            << "\n";
  EXPECT_GT(blue_excess(500, 180), blue_excess(500, 220) + 20);
}

// The local model's contact patch in the top view: its red part (over the
// end-post gap) covers R of the model in pixels, lies over the drawn gap,
// and is absent while the patch is clear of the gap.
TEST(CrossingRender, TopViewShowsTheLocalModelsPatchAndItsPartOverTheGap) {
  RenderSettings s = contact_view();
  s.view = RenderView::top;
  JointParams joint;  // theta 30 deg
  joint.gap_m = 0.006;
  PressureInputs in;  // table 6.1: an ellipse 16 x 12 mm
  in.gap = EndPostGap{joint.gap_m, joint.theta_rad};
  // The patch centre is moved onto the head: y_c = b_t - b/2 = 14 mm; the
  // gap's centre line crosses that y at x = 14 mm cot 30 deg = 24.25 mm.
  const double y_c = 0.014, x_line = y_c / std::tan(joint.theta_rad);
  auto trajectory_at = [&](double contact_x) {
    Trajectory t;
    for (int i = 0; i <= 2; ++i) {
      WheelSample w = at(i * 1e-4, {contact_x, kYw, kR + 0.001});
      ContactSample c;
      c.point_on_rail_m = {contact_x, kYw, 0.0};
      w.contacts.push_back(c);
      t.samples.push_back(w);
    }
    return t;
  };
  const RailJointMesh rails = build_rail_joint_mesh(joint);
  // Red as drawn: palette::patch_over_gap, lit, possibly under the 35 %
  // see-through wheel (which turns it purple, not blue): red well above
  // green and blue. The cut line (palette::rail_cut) is as red; it runs along
  // the gap's near edge, so only its pixels inside the patch are counted too.
  auto is_red = [](const std::uint8_t* p) { return p[0] >= p[1] + 60 && p[0] >= p[2] + 40; };

  for (const double offset_m : {0.002, -0.025}) {
    TopView renderer(s, rails, build_wheel_mesh(test_wheel(), 512, 0.0), trajectory_at(x_line + offset_m));
    renderer.show_contact_patch(in);
    RgbImage image;
    renderer.render_at(1e-4, image);
    const std::optional<PatchPlacement> placement = renderer.contact_patch_at(1e-4);
    ASSERT_TRUE(placement.has_value());
    const Camera camera = renderer.camera_at(1e-4);
    const double px_per_m = s.width_px / camera.visible_width_m;
    auto pixel_of = [&](double x, double y) {
      const Eigen::Vector4d clip = camera.projection * camera.view * Eigen::Vector4d(x, y, 0.0, 1.0);
      return Eigen::Vector2d(0.5 * (clip.x() / clip.w() + 1.0) * s.width_px, 0.5 * (1.0 - clip.y() / clip.w()) * s.height_px);
    };
    // Search the patch's bounding box (8 x 6 mm half-sizes) plus 2 px.
    const Eigen::Vector2d lo = pixel_of(x_line + offset_m - 0.008, y_c + 0.006);
    const Eigen::Vector2d hi = pixel_of(x_line + offset_m + 0.008, y_c - 0.006);
    long long red = 0;
    double worst_outside_gap_px = 0.0;
    for (int row = static_cast<int>(lo.y()) - 2; row <= static_cast<int>(hi.y()) + 2; ++row) {
      for (int col = static_cast<int>(lo.x()) - 2; col <= static_cast<int>(hi.x()) + 2; ++col) {
        const double y = y_c - (row + 0.5 - pixel_of(0.0, y_c).y()) / px_per_m;
        const double x = x_line + offset_m + (col + 0.5 - pixel_of(x_line + offset_m, y_c).x()) / px_per_m;
        // Inside the patch's ellipse grown by 2 px (its blended outline), so
        // the cut line away from the patch is not counted.
        const double grow = 2.0 / px_per_m;
        const double ex = (x - x_line - offset_m) / (0.008 + grow), ey = (y - y_c) / (0.006 + grow);
        if (ex * ex + ey * ey > 1.0 || !is_red(image.pixel(col, row))) continue;
        ++red;
        // How far outside the drawn gap x in [y cot - g_long/2, y cot + g_long/2] the pixel lies.
        const double half_gap = joint.gap_m / std::sin(joint.theta_rad) / 2.0;
        const double outside = std::abs(x - y / std::tan(joint.theta_rad)) - half_gap;
        worst_outside_gap_px = std::max(worst_outside_gap_px, outside * px_per_m);
      }
    }
    const double expected = placement->state.reduction_area_m2 * px_per_m * px_per_m;
    std::cout << "patch centre " << offset_m * 1e3 << " mm ahead of the gap's centre line: " << red
              << " red pixels in it, R s^2 = " << expected << " px, the farthest " << worst_outside_gap_px
              << " px outside the gap\n";
    if (offset_m < 0.0) {
      // 25 mm behind: clear of the gap (more than 19.1 mm, joint_contact_patch_test).
      EXPECT_EQ(placement->state.reduction_area_m2, 0.0);
      EXPECT_EQ(red, 0);
      continue;
    }
    // The red region's outline blends with its neighbours (FXAA, and the
    // pixel grid): up to half its perimeter either way, about 2 (12 mm
    // chords) + the arc, 40 mm at 6000 px/m = 240 px; and the cut line, 2 px
    // wide along the near edge, adds up to a chord's length (84 px) on the
    // bearing side. Together 330 px of about 3,000.
    EXPECT_GT(expected, 2000.0);
    EXPECT_NEAR(static_cast<double>(red), expected, 330.0);
    // Every red pixel over the gap, to the edge's blend and the cut line's 2 px.
    EXPECT_LE(worst_outside_gap_px, 2.5);
  }
}

// Found by review: on a square joint with a gap, the frame at the impact
// (--impact-frame: t = the located impact time) put the patch on the
// incoming rail's contact, 14.5 mm behind the impact ring, because the
// recorded sample nearer to that instant was the one before the impact. Here
// samples at 0, 0.1 and 0.2 ms touch at x = -10 mm (incoming) until the last,
// which touches the struck corner at x = +3 mm; the impact is located at
// 0.12 ms, nearer to the 0.1 ms sample. From the impact to the end of its step
// the patch must be centred on the struck point; before it, on the incoming
// contact.
TEST(CrossingRender, TopViewPatchIsOnTheStruckPointFromTheImpactOn) {
  RenderSettings s = contact_view();
  s.view = RenderView::top;
  JointParams joint;
  joint.theta_rad = std::numbers::pi / 2.0;
  joint.gap_m = 0.004;
  PressureInputs in;  // table 6.1: an ellipse 16 x 12 mm
  in.gap = EndPostGap{joint.gap_m, joint.theta_rad};
  const double incoming_x = -0.010, struck_x = 0.003;
  Trajectory t;
  for (int i = 0; i <= 2; ++i) {
    const double x = i < 2 ? incoming_x : struck_x;
    WheelSample w = at(i * 1e-4, {x, kYw, kR});
    ContactSample c;
    c.point_on_rail_m = {x, kYw, 0.0};
    w.contacts.push_back(c);
    t.samples.push_back(w);
  }
  ImpactEvent impact;
  impact.time_s = 1.2e-4;
  impact.contact_point_m = {struck_x, kYw, 0.0};
  impact.first_sample = impact.last_sample = 2;
  t.impacts.push_back(impact);
  TopView renderer(s, build_rail_joint_mesh(joint), build_wheel_mesh(test_wheel(), 64, 0.0), t);
  renderer.show_contact_patch(in);
  const double half_width_m = joint.half_width_m;
  const double front_at_struck = place_contact_patch(in, {struck_x, kYw}, half_width_m).x_front_m;
  const double front_at_incoming = place_contact_patch(in, {incoming_x, kYw}, half_width_m).x_front_m;
  ASSERT_NE(front_at_struck, front_at_incoming);
  for (const double t_s : {1.2e-4, 1.5e-4, 2e-4}) {
    const std::optional<PatchPlacement> placement = renderer.contact_patch_at(t_s);
    ASSERT_TRUE(placement.has_value()) << t_s;
    EXPECT_DOUBLE_EQ(placement->x_front_m, front_at_struck) << "t = " << t_s * 1e3 << " ms";
  }
  // Before the impact: the incoming rail's contact.
  EXPECT_DOUBLE_EQ(renderer.contact_patch_at(1.1e-4)->x_front_m, front_at_incoming);
}

// A perspective frame, width_px x height_px, of the wheel resting on the
// incoming rail (eleven samples, no impact), drawn at 0.5 ms.
struct PerspectiveFrame {
  RenderSettings settings;
  std::unique_ptr<PerspectiveView> renderer;
  RgbImage image;
};
PerspectiveFrame perspective_frame(int width_px, int height_px) {
  PerspectiveFrame frame;
  frame.settings = contact_view();
  frame.settings.width_px = width_px;
  frame.settings.height_px = height_px;
  frame.settings.view = RenderView::perspective;
  Trajectory t;
  for (int i = 0; i <= 10; ++i) t.samples.push_back(resting_with_contact(i * 1e-4, -0.25 + 0.01 * i));
  frame.renderer = std::make_unique<PerspectiveView>(frame.settings, build_rail_joint_mesh(JointParams{}),
                                                      fine_wheel(frame.settings), t);
  frame.renderer->render_at(0.5e-3, frame.image);
  return frame;
}

TEST(CrossingRender, PerspectiveViewShowsTheWholeWheelOnTheRailsAndTheContactInTheInset) {
  const PerspectiveFrame frame = perspective_frame(960, 540);
  const PerspectiveView& view = *frame.renderer;
  const RgbImage& image = frame.image;
  const PixelRect overview = view.overview_rect(), inset = view.inset_rect();
  std::cout << "overview " << overview.width << "x" << overview.height << " at (" << overview.x << ", " << overview.y
            << "), inset " << inset.width << "x" << inset.height << " at (" << inset.x << ", " << inset.y << ")\n";
  // Side by side, not overlapping: the inset never covers the overview.
  EXPECT_LE(overview.x + overview.width, inset.x);

  // The overview camera holds the whole wheel: every rim point projects into the overview.
  const Camera& camera = view.overview_camera();
  const Eigen::Vector3d centre = resting_on_incoming(-0.20);
  auto project = [&](const Eigen::Vector3d& p) {
    const Eigen::Vector4d clip = camera.projection * camera.view * p.homogeneous();
    return Eigen::Vector2d(overview.x + 0.5 * (clip.x() / clip.w() + 1.0) * overview.width,
                           overview.y + 0.5 * (1.0 - clip.y() / clip.w()) * overview.height);
  };
  double u_lo = 1e9, u_hi = -1e9, v_lo = 1e9, v_hi = -1e9;
  for (int j = 0; j < 64; ++j) {
    const double phi = 2.0 * std::numbers::pi * j / 64;
    const Eigen::Vector2d p = project(centre + kR * Eigen::Vector3d(std::cos(phi), 0.0, std::sin(phi)));
    u_lo = std::min(u_lo, p.x());
    u_hi = std::max(u_hi, p.x());
    v_lo = std::min(v_lo, p.y());
    v_hi = std::max(v_hi, p.y());
  }
  std::cout << "projected rim: u " << u_lo << " .. " << u_hi << ", v " << v_lo << " .. " << v_hi << "\n";
  EXPECT_GE(u_lo, overview.x);
  EXPECT_LE(u_hi, overview.x + overview.width);
  EXPECT_GE(v_lo, overview.y);
  EXPECT_LE(v_hi, overview.y + overview.height);
  // ... and fills it: the fit stands as close as the margins allow, so the
  // wheel spans most of the height (the rails' ends below it take the rest).
  EXPECT_GT(v_hi - v_lo, 0.6 * overview.height);

  // The wheel's pixels (clear blue) in the overview: their extent is the projected rim's, within 3 px.
  int wu_lo = 1 << 30, wu_hi = -1, wv_lo = 1 << 30, wv_hi = -1;
  for (int row = overview.y; row < overview.y + overview.height; ++row)
    for (int col = overview.x; col < overview.x + overview.width; ++col) {
      if (!is_wheel(image.pixel(col, row))) continue;
      wu_lo = std::min(wu_lo, col);
      wu_hi = std::max(wu_hi, col + 1);
      wv_lo = std::min(wv_lo, row);
      wv_hi = std::max(wv_hi, row + 1);
    }
  std::cout << "wheel pixels: u " << wu_lo << " .. " << wu_hi << ", v " << wv_lo << " .. " << wv_hi << "\n";
  EXPECT_NEAR(wu_lo, u_lo, 3.0);
  EXPECT_NEAR(wu_hi, u_hi, 3.0);
  EXPECT_NEAR(wv_lo, v_lo, 3.0);
  // The bottom of the wheel stands on the rail: the rail may hide a pixel or two of it.
  EXPECT_NEAR(wv_hi, v_hi, 3.0);

  // The inset looks at the wheel's drawn lowest point, which projects to its
  // centre: in the inset's centre column the wheel ends there.
  const int inset_col = inset.x + inset.width / 2, inset_row = inset.y + inset.height / 2;
  int lowest = -1;
  for (int row = inset.y; row < inset.y + inset.height; ++row) {
    if (is_wheel(image.pixel(inset_col, row))) lowest = row;
  }
  std::cout << "inset: lowest wheel pixel in column " << inset_col << " at row " << lowest << ", centre row "
            << inset_row << "\n";
  EXPECT_NEAR(lowest + 1, inset_row, 3.0);
}

// A 640 x 360 perspective frame has room for the legend at 1x only in short
// (the full one ran off the frame's right and bottom edges): every pixel of
// legend text lies inside the panel below the inset, clear of the frame's
// last three columns and rows. Text is the palette's near-black; nothing
// else in the panel is that dark (no impact here, so no orange border).
TEST(CrossingRender, PerspectiveLegendFitsASmallFrame) {
  const PerspectiveFrame frame = perspective_frame(640, 360);
  const RenderSettings& s = frame.settings;
  const RgbImage& image = frame.image;
  const PixelRect inset = frame.renderer->inset_rect();
  auto is_text = [](const std::uint8_t* p) { return p[0] < 60 && p[1] < 60 && p[2] < 60; };
  int text_pixels = 0, at_the_edge = 0;
  for (int row = inset.y + inset.height + 2; row < s.height_px; ++row) {
    for (int col = inset.x; col < s.width_px; ++col) {
      if (!is_text(image.pixel(col, row))) continue;
      ++text_pixels;
      if (col >= s.width_px - 3 || row >= s.height_px - 3) ++at_the_edge;
    }
  }
  std::cout << "legend text pixels " << text_pixels << ", at the frame's edge " << at_the_edge << "\n";
  EXPECT_GT(text_pixels, 1000);  // the legend is there (about ten lines of text)
  EXPECT_EQ(at_the_edge, 0);
}

}  // namespace
}  // namespace railjoint
