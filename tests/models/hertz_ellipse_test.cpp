// Hertz's approach constant of the elliptical point contact
// (models/hertz_ellipse.h) against closed forms (the sphere, the cylinder)
// and an independent numerical integration of Boussinesq's displacement
// under the ellipse's pressure, written here without elliptic integrals.

#include <cmath>
#include <cstdio>
#include <numbers>

#include <gtest/gtest.h>

#include "models/hertz_ellipse.h"

namespace railjoint {
namespace {

constexpr double kPi = std::numbers::pi;

HertzMaterial steel() { return HertzMaterial{0.3, 210e9, 0.3}; }

// E* of two steel bodies: E / (2 (1 - nu^2)) = 210e9 / 1.82.
constexpr double kSteelContactModulus_Pa = 210e9 / 1.82;

// Equal curvatures A = B = 1 / (2 R): Hertz's sphere on a plane of the same
// relative radius R (Johnson eqs. 4.22-4.23): a^3 = 3 P R / (4 E*),
// delta = a^2 / R, so G = (9 / (16 E*^2 R))^(1/3).
TEST(EllipticalHertz, EqualCurvaturesGiveTheSphere) {
  for (const double R : {0.3, 0.475, 0.5}) {
    const auto hertz = elliptical_hertz({0.5 / R, 0.5 / R}, steel());
    ASSERT_TRUE(hertz.has_value());
    const double G = std::cbrt(9.0 / (16.0 * kSteelContactModulus_Pa * kSteelContactModulus_Pa * R));
    EXPECT_NEAR(hertz->hertz_constant_m_per_N2_3, G, 1e-12 * G) << R;
    const HertzPatch patch = hertz_patch(*hertz, 1e5);
    const double a = std::cbrt(3.0 * 1e5 * R / (4.0 * kSteelContactModulus_Pa));
    EXPECT_NEAR(patch.semi_axis_x_m, a, 1e-12 * a);
    EXPECT_NEAR(patch.semi_axis_y_m, a, 1e-12 * a);
    EXPECT_NEAR(patch.approach_m, a * a / R, 1e-11 * a * a / R);
    EXPECT_NEAR(patch.max_pressure_Pa, 3.0 * 1e5 / (2.0 * kPi * a * a), 1e-9 * patch.max_pressure_Pa);
  }
}

// Boussinesq: a pressure p on the half-space's surface displaces the point
// under the origin by (1 / (pi E*)) integral p / rho dA for both bodies
// together. Over the ellipse p0 sqrt(1 - x^2/a^2 - y^2/b^2), in polar
// coordinates about the centre (rho_max(phi) the ellipse's radius in the
// direction phi), the radial integral of sqrt(1 - rho^2 / rho_max^2) is
// pi rho_max / 4, so delta = (p0 / (4 E*)) integral_0^2pi rho_max(phi) dphi.
// The approach is that displacement (the far points move by it while the
// centre's gap closes), evaluated here by the midpoint rule, which converges
// exponentially on a smooth periodic integrand.
double boussinesq_approach_m(double a_m, double b_m, double p0_Pa, double contact_modulus_Pa) {
  const int n = 20000;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    const double phi = (i + 0.5) * 2.0 * kPi / n;
    const double c = std::cos(phi) / a_m;
    const double s = std::sin(phi) / b_m;
    sum += 1.0 / std::sqrt(c * c + s * s);
  }
  return p0_Pa / (4.0 * contact_modulus_Pa) * sum * 2.0 * kPi / n;
}

// The wheel-rail range and beyond: a 0.475 m wheel on 300, 80 and 13 mm head
// arcs, a dip's bend, a hollow tread and ratios up to 1e4.
TEST(EllipticalHertz, ApproachMatchesBoussinesqIntegration) {
  const double R = 0.475;
  const RelativeCurvatures cases[] = {
      {0.5 / R, 0.5 / 0.3}, {0.5 / R, 0.5 / 0.08}, {0.5 / R, 0.5 / 0.013}, {0.5 / R + 0.5 / 2.0, 0.5 / 0.3},
      {0.5 / R, 0.5 / 0.3 - 0.5 / 0.6}, {1.0, 3.0}, {3.0, 1.0}, {1.0, 100.0}, {1.0, 1e4}};
  double worst = 0.0;
  for (const RelativeCurvatures& k : cases) {
    const auto hertz = elliptical_hertz(k, steel());
    ASSERT_TRUE(hertz.has_value());
    for (const double P : {1.0, 1e5}) {
      const HertzPatch patch = hertz_patch(*hertz, P);
      const double reference =
          boussinesq_approach_m(patch.semi_axis_x_m, patch.semi_axis_y_m, patch.max_pressure_Pa, kSteelContactModulus_Pa);
      const double error = std::abs(patch.approach_m / reference - 1.0);
      worst = std::max(worst, error);
      // The midpoint rule with 2e4 points: measured 1.6e-13 at worst, the
      // ratio 1e4 (b/a ~ 3e-3, the integrand's peak some 60 points wide)
      // included; 1e-11 leaves room for another libm.
      EXPECT_LT(error, 1e-11) << k.along_x_per_m << " " << k.across_y_per_m << " " << P;
    }
  }
  std::printf("worst relative difference from Boussinesq's integral: %.2e\n", worst);
}

// A long, thin ellipse (A / B -> 0) is locally the cylinder's line contact
// (Johnson eqs. 4.43-4.45): with q = pi p0 b / 2 the load per length on its
// centre line, b = sqrt(4 q R / (pi E*)), R = 1 / (2 B). Hertz's ellipse
// reaches it as E(e) -> 1, off by O((b/a)^2 ln(a/b)).
TEST(EllipticalHertz, ThinEllipseTendsToTheCylinder) {
  const double B = 0.5 / 0.3;
  double previous = 1.0;
  for (const double ratio : {1e-2, 1e-4, 1e-6}) {
    const auto hertz = elliptical_hertz({ratio * B, B}, steel());
    ASSERT_TRUE(hertz.has_value());
    const HertzPatch patch = hertz_patch(*hertz, 1e5);
    const double q = kPi * patch.max_pressure_Pa * patch.semi_axis_y_m / 2.0;
    const double b_cylinder = std::sqrt(4.0 * q * 0.3 / (kPi * kSteelContactModulus_Pa));
    const double error = std::abs(patch.semi_axis_y_m / b_cylinder - 1.0);
    std::printf("A/B = %.0e: b / b_cylinder - 1 = %.2e\n", ratio, error);
    EXPECT_LT(error, previous);
    previous = error;
  }
  // Measured 2.1e-3, 2.3e-5 and 2.4e-7 at A/B = 1e-2, 1e-4, 1e-6: falling
  // as A/B, as (b/a)^2 ln(a/b) does.
  EXPECT_LT(previous, 1e-6);
}

// A line (a cone on the flat head), a hollow tread conforming to the head,
// and an edge have no elliptical constant: the caller keeps its empirical one.
TEST(EllipticalHertz, LinesHollowsAndEdgesHaveNone) {
  EXPECT_FALSE(elliptical_hertz({1.0, 0.0}, steel()).has_value());
  EXPECT_FALSE(elliptical_hertz({1.0, -0.5}, steel()).has_value());
  EXPECT_FALSE(elliptical_hertz({INFINITY, 1.0}, steel()).has_value());
  EXPECT_FALSE(elliptical_hertz({NAN, 1.0}, steel()).has_value());
  EXPECT_FALSE(elliptical_hertz({1.0, 1e20}, steel()).has_value());
}

// The curvatures add as the gap's: a 0.475 m wheel rolling on a 300 mm crown
// with a dip bent at 1/2 m: A = (1/0.475 + 1/2)/2, B = (0 + 1/0.3)/2.
TEST(EllipticalHertz, CurvaturesAddAsTheGap) {
  ContactCurvatures k;
  k.wheel_along_x_per_m = 1.0 / 0.475;
  k.rail_along_x_per_m = 0.5;
  k.rail_across_y_per_m = 1.0 / 0.3;
  const RelativeCurvatures r = relative_curvatures(k);
  EXPECT_DOUBLE_EQ(r.along_x_per_m, 0.5 * (1.0 / 0.475 + 0.5));
  EXPECT_DOUBLE_EQ(r.across_y_per_m, 0.5 / 0.3);
}

}  // namespace
}  // namespace railjoint
