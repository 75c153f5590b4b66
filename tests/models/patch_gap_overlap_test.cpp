// The patch's area over the end-post gap (models/patch_gap_overlap.h) against
// references that share no code with it: closed forms of an ellipse cut by
// two parallel lines, Boost.Geometry on a fine polygon, finite differences,
// and the limits of a vanishing gap and a square joint.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "models/patch_gap_overlap.h"

namespace railjoint {
namespace {

constexpr double kPi = std::numbers::pi;

double radians(double degrees) { return degrees * kPi / 180.0; }

// Table 6.1: a = 16 mm, b = 12 mm, g = 6 mm.
ContactPatch table_6_1_ellipse() { return ContactPatch{PatchShape::ellipse, 0.016, 0.012, 100}; }

// Area of the unit disc between the lines s = s1 and s = s2 (s1 <= s2):
// integral of 2 sqrt(1 - s^2) ds = F(s2) - F(s1), F(s) = asin s + s sqrt(1 - s^2).
double strip_of_unit_disc(double s1, double s2) {
  const auto F = [](double s) {
    s = std::clamp(s, -1.0, 1.0);
    return std::asin(s) + s * std::sqrt(1.0 - s * s);
  };
  return F(s2) - F(s1);
}

// The ellipse spans 0 <= y <= b like the parallelogram, so the parallelogram
// cuts it like the band 0 <= n.p <= g between the two cut lines. Mapped to the
// unit disc, the band is s1 <= s <= s2 with s = (n.p - n.c) / h, where
// h = sqrt((a/2 n_x)^2 + (b/2 n_y)^2): R = (a/2)(b/2) (F(s2) - F(s1)), and
// dR/dx_front = (a/2)(b/2) (F'(s2) - F'(s1)) ds/dx with ds/dx = -sin(theta) / h.
struct Strip {
  double area_m2;
  double d_area_d_x_m;
};
Strip band_closed_form(const ContactPatch& patch, double gap_m, double theta_rad, double x_front_m) {
  const double A = patch.length_m / 2.0;
  const double B = patch.width_m / 2.0;
  const double nx = std::sin(theta_rad);
  const double ny = -std::cos(theta_rad);
  const double h = std::hypot(A * nx, B * ny);
  const double centre = nx * (x_front_m - A) + ny * B;
  const double s1 = -centre / h;
  const double s2 = (gap_m - centre) / h;
  const auto dF = [](double s) { return std::abs(s) >= 1.0 ? 0.0 : 2.0 * std::sqrt(1.0 - s * s); };
  return {A * B * strip_of_unit_disc(s1, s2), A * B * (dF(s2) - dF(s1)) * (-nx / h)};
}

double x_end(const ContactPatch& patch, const EndPostGap& gap) {
  return gap_parallelogram_m(gap, patch.width_m)[2].x() + patch.length_m;
}

TEST(UnitDiscPolygonArea, WholeDiscHalfDiscAndOrientation) {
  const std::vector<Eigen::Vector2d> big_square = {{-2, -2}, {2, -2}, {2, 2}, {-2, 2}};
  EXPECT_NEAR(unit_disc_polygon_area(big_square), kPi, 1e-15);
  const std::vector<Eigen::Vector2d> right_half = {{0, -2}, {2, -2}, {2, 2}, {0, 2}};
  EXPECT_NEAR(unit_disc_polygon_area(right_half), kPi / 2.0, 1e-15);
  const std::vector<Eigen::Vector2d> clockwise(big_square.rbegin(), big_square.rend());
  EXPECT_NEAR(unit_disc_polygon_area(clockwise), -kPi, 1e-15);
  // A square inside the disc is all triangle: side 1, area 1.
  const std::vector<Eigen::Vector2d> inner = {{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}};
  EXPECT_NEAR(unit_disc_polygon_area(inner), 1.0, 1e-15);
}

// The closed form for the square joint, patch centred over the gap:
// the ellipse strip |x| <= g/2 has area 2 (a/2)(b/2) [asin(u) + u sqrt(1 - u^2)], u = g/a.
TEST(PatchGapOverlap, SquareJointCentredIsTheEllipseStrip) {
  const ContactPatch patch = table_6_1_ellipse();
  for (double g : {0.001, 0.006, 0.012, 0.0159}) {
    const EndPostGap gap{g, kPi / 2.0};
    const double u = g / patch.length_m;
    const double expected = 2.0 * (patch.length_m / 2.0) * (patch.width_m / 2.0) * (std::asin(u) + u * std::sqrt(1.0 - u * u));
    // Centred: the ellipse's centre at x = g/2, so x_front = g/2 + a/2.
    const GapOverlap overlap = patch_gap_overlap(patch, gap, g / 2.0 + patch.length_m / 2.0);
    std::printf("g = %.4f m: R = %.15e m^2, closed form %.15e, dR/dx = %.3e\n", g, overlap.area_m2, expected,
                overlap.d_area_d_x_front_m);
    // Residual ~2e-20 m^2 (1e-16 of R): round-off of atan2 and the products.
    EXPECT_NEAR(overlap.area_m2, expected, 1e-14 * expected);
    EXPECT_NEAR(overlap.d_area_d_x_front_m, 0.0, 1e-14 * patch.width_m) << "symmetric: no change";
  }
}

class OverlapAtAngle : public testing::TestWithParam<double> {};

// The edge-sum route against the band closed form over the whole traversal.
TEST_P(OverlapAtAngle, EqualsTheBandClosedFormEverywhere) {
  const ContactPatch patch = table_6_1_ellipse();
  const EndPostGap gap{0.006, radians(GetParam())};
  const double A0 = kPi * patch.length_m * patch.width_m / 4.0;
  const double end = x_end(patch, gap);
  double worst_area = 0.0;
  double worst_rate = 0.0;
  for (int i = 0; i <= 400; ++i) {
    const double x = end * i / 400.0;
    const GapOverlap overlap = patch_gap_overlap(patch, gap, x);
    const Strip expected = band_closed_form(patch, gap.gap_m, gap.theta_rad, x);
    worst_area = std::max(worst_area, std::abs(overlap.area_m2 - expected.area_m2) / A0);
    worst_rate = std::max(worst_rate, std::abs(overlap.d_area_d_x_front_m - expected.d_area_d_x_m) / patch.width_m);
  }
  std::printf("theta = %g deg: worst |R - closed form| / A0 = %.2e, worst |dR/dx - closed form| / b = %.2e\n",
              GetParam(), worst_area, worst_rate);
  // Residuals up to ~1e-15 (round-off of atan2 sums and of the chord roots).
  EXPECT_LT(worst_area, 1e-13);
  EXPECT_LT(worst_rate, 1e-12);
}

// The derivative against a central difference of the area itself.
TEST_P(OverlapAtAngle, DerivativeMatchesCentralDifference) {
  const ContactPatch patch = table_6_1_ellipse();
  const EndPostGap gap{0.006, radians(GetParam())};
  const double end = x_end(patch, gap);
  const double step = 1e-7;  // m: truncation (R''' step^2 ~ 1e-14 m) above round-off (1e-16 R / step ~ 1e-13)
  double worst = 0.0;
  for (int i = 1; i < 200; ++i) {
    const double x = end * i / 200.0;
    const double difference = (patch_gap_overlap(patch, gap, x + step).area_m2 -
                               patch_gap_overlap(patch, gap, x - step).area_m2) / (2.0 * step);
    worst = std::max(worst, std::abs(patch_gap_overlap(patch, gap, x).d_area_d_x_front_m - difference) / patch.width_m);
  }
  std::printf("theta = %g deg: worst |dR/dx - central difference| / b = %.2e\n", GetParam(), worst);
  // Measured 1e-9 .. 4e-8 (largest where the chord is short and R'' steep, at the touches).
  EXPECT_LT(worst, 5e-7);
}

INSTANTIATE_TEST_SUITE_P(Angles, OverlapAtAngle, testing::Values(1.0, 5.0, 30.0, 45.0, 60.0, 89.9, 90.0));

// Boost.Geometry on the inscribed n-gon (the thesis's polygon, closed) converges
// on the exact ellipse area as 1/n^2: the n-gon misses a sliver of height
// ~ (pi/n)^2 r/2 along the part of the outline inside the gap.
TEST(PatchGapOverlap, BoostPolygonConvergesOnTheExactAreaAsInverseSquare) {
  const ContactPatch ellipse = table_6_1_ellipse();
  const EndPostGap gap{0.006, radians(30.0)};
  const auto corners = gap_parallelogram_m(gap, ellipse.width_m);
  const std::vector<Eigen::Vector2d> gap_polygon(corners.begin(), corners.end());
  const double x_front = 0.018;  // the front past the gap, the back still before it: a cut on both sides
  const double exact = patch_gap_overlap(ellipse, gap, x_front).area_m2;
  std::vector<double> errors;
  for (int n : {1024, 4096, 16384}) {
    const ContactPatch polygon{PatchShape::polygon, ellipse.length_m, ellipse.width_m, n};
    const double boost_area = polygon_intersection_area_m2(patch_polygon_m(polygon, x_front), gap_polygon);
    errors.push_back((exact - boost_area) / exact);
    std::printf("n = %5d: Boost.Geometry %.15e m^2, exact %.15e m^2, relative deficit %.3e\n", n, boost_area, exact,
                errors.back());
  }
  // n = 16384: 2.0e-8 measured; each 4x in n divides the deficit by 16.0.
  EXPECT_GT(errors[2], 0.0) << "an inscribed polygon has less area";
  EXPECT_LT(errors[2], 3e-8);
  EXPECT_NEAR(errors[0] / errors[1], 16.0, 0.5);
  EXPECT_NEAR(errors[1] / errors[2], 16.0, 0.5);
}

// g -> 0: the band is a line of width g across the ellipse, R -> g times the
// chord of the ellipse along the cut through... wherever the line crosses it;
// centred, the chord through the centre along t = (cos theta, sin theta),
// 2 / sqrt(cos^2 / (a/2)^2 + sin^2 / (b/2)^2).
TEST(PatchGapOverlap, VanishingGapIsGapTimesTheChord) {
  const ContactPatch patch = table_6_1_ellipse();
  for (double theta_deg : {10.0, 30.0, 60.0, 90.0}) {
    const double theta = radians(theta_deg);
    const double g = 1e-7;
    const EndPostGap gap{g, theta};
    const double A = patch.length_m / 2.0;
    const double B = patch.width_m / 2.0;
    const double chord = 2.0 / std::sqrt(std::pow(std::cos(theta) / A, 2) + std::pow(std::sin(theta) / B, 2));
    // Centre of the parallelogram: ((b cot + g_long) / 2, b / 2); the ellipse's centre there.
    const double x_front = (patch.width_m / std::tan(theta) + g / std::sin(theta)) / 2.0 + A;
    const double R = patch_gap_overlap(patch, gap, x_front).area_m2;
    std::printf("theta = %g deg: R / g = %.12e m, chord %.12e m\n", theta_deg, R / g, chord);
    // Relative O(g^2 / a^2) ~ 1e-10, plus round-off of R (~1e-16 A0) over g: measured 3e-11.
    EXPECT_NEAR(R / g, chord, 1e-7 * chord);
  }
}

// theta -> 90 deg: the inclined gap turns continuously into the square one.
TEST(PatchGapOverlap, SquareJointIsTheLimitOfInclinedOnes) {
  const ContactPatch patch = table_6_1_ellipse();
  const EndPostGap square{0.006, kPi / 2.0};
  for (double x : {0.003, 0.008, 0.011, 0.015, 0.02}) {
    const GapOverlap at_90 = patch_gap_overlap(patch, square, x);
    for (double delta : {1e-3, 1e-5}) {
      const GapOverlap near_90 = patch_gap_overlap(patch, EndPostGap{0.006, kPi / 2.0 - delta}, x);
      // First order in delta: the cut lines tilt by delta, moving the patch's
      // crossing by about (b/2) delta: |dR| <~ chord * b/2 * delta.
      EXPECT_NEAR(near_90.area_m2, at_90.area_m2, patch.width_m * patch.width_m * delta) << x << ' ' << delta;
    }
  }
}

}  // namespace
}  // namespace railjoint
