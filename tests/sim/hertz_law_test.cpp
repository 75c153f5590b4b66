// Hertz's contact law and Hunt and Crossley's dissipation (sim/hertz_law.h):
// the published constant of a new wheel, force and approach as inverses,
// the tangent stiffness against a finite difference and the textbook range,
// and the limits of the damped law.

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "sim/hertz_law.h"

namespace railjoint {
namespace {

// G = 3.86e-8 R^-0.115 (Jenkins et al. 1974; Zhai 2020, section 2.4). By hand
// at R = 0.475 m: ln 0.475 = -0.744440, x -0.115 = 0.0856107, exp = 1.089382,
// x 3.86e-8 = 4.2050e-8 m/N^(2/3).
TEST(HertzLaw, DefaultConstantOfANewWheelIsThePublishedFormula) {
  const double g = default_hertz_constant_m_per_N2_3(0.475);
  const double published = 3.86e-8 * std::pow(0.475, -0.115);
  std::printf("G(0.475 m) = %.8e m/N^(2/3) (formula %.8e, by hand 4.2050e-8)\n", g, published);
  // The same expression evaluated twice: only round-off, 1e-12 relative is ~1e4 ulp.
  EXPECT_NEAR(g, published, 1e-12 * published);
  // The hand value to 4 digits: its rounding is half a unit of the 4th digit, 5e-13.
  EXPECT_NEAR(g, 4.2050e-8, 0.00005e-8);
}

TEST(HertzLaw, ForceAndApproachAreInverses) {
  const double g = 4.2e-8;
  double worst_force = 0.0;
  double worst_approach = 0.0;
  for (int decade = 0; decade <= 60; ++decade) {  // 1 N .. 1 MN, 10 points a decade
    const double force_N = std::pow(10.0, decade / 10.0);
    const double approach_m = hertz_approach_m(g, force_N);
    worst_force = std::max(worst_force, std::abs(hertz_force_N(g, approach_m) / force_N - 1.0));
    worst_approach = std::max(worst_approach, std::abs(hertz_approach_m(g, hertz_force_N(g, approach_m)) / approach_m - 1.0));
  }
  std::printf("round trip over 1 N..1 MN: worst relative error force %.3g, approach %.3g\n", worst_force,
              worst_approach);
  // Four or five correctly rounded operations, each 1.1e-16, amplified at most 1.5x by the power:
  // under 1e-15; 1e-14 is ~10x above.
  EXPECT_LT(worst_force, 1e-14);
  EXPECT_LT(worst_approach, 1e-14);
}

TEST(HertzLaw, NoForceWithoutPenetration) {
  const double g = 4.2e-8;
  std::printf("force at 0: %g N, at -0: %g N, at -1 um: %g N\n", hertz_force_N(g, 0.0), hertz_force_N(g, -0.0),
              hertz_force_N(g, -1e-6));
  EXPECT_EQ(hertz_force_N(g, 0.0), 0.0);
  EXPECT_EQ(hertz_force_N(g, -0.0), 0.0);
  EXPECT_EQ(hertz_force_N(g, -1e-6), 0.0);
  EXPECT_EQ(hertz_force_N(g, -1.0), 0.0);
}

// The tangent dF/d delta at P0 = 100 kN against a central difference of the
// law itself, and against the textbook K_H: 1.5 P0^(1/3) / G = 1.5 x 46.4159 /
// 4.2e-8 = 1.6577e9 N/m at G = 4.2e-8, inside the 1.4e9..1.8e9 N/m that
// track-dynamics texts quote for a wheel at ~100 kN.
TEST(HertzLaw, LinearisedStiffnessIsTheTangentOfTheLaw) {
  const double g = 4.2e-8;
  const double p0_N = 100e3;
  const double delta_m = hertz_approach_m(g, p0_N);
  // h = 1e-3 delta: truncation h^2 F''' / (6 F') = -(h / delta)^2 / 24 = -4e-8
  // relative; round-off 1.1e-16 F / (h F') = 7e-14.
  const double h_m = 1e-3 * delta_m;
  const double difference = (hertz_force_N(g, delta_m + h_m) - hertz_force_N(g, delta_m - h_m)) / (2.0 * h_m);
  const double k = linearised_hertz_stiffness_N_per_m(g, p0_N);
  std::printf("K_H at 100 kN, G = 4.2e-8: %.6e N/m (by hand 1.6577e9); central difference %.6e, relative %.3g\n", k,
              difference, k / difference - 1.0);
  // The difference's own error is 4e-8 by the estimate above; 1e-6 is 25x above.
  EXPECT_NEAR(k / difference, 1.0, 1e-6);
  EXPECT_GT(k, 1.4e9);
  EXPECT_LT(k, 1.8e9);
}

TEST(HuntCrossley, NoDampingOrAContactMadeAtRestIsPureHertz) {
  const double g = 4.2e-8;
  const double delta_m = 9e-5;
  const double hertz = hertz_force_N(g, delta_m);
  const double elastic = hunt_crossley_force_N(g, 0.0, delta_m, 0.7, 1.2);
  const double elastic_rebound = hunt_crossley_force_N(g, 0.0, delta_m, -0.7, 1.2);
  const double made_at_rest = hunt_crossley_force_N(g, 0.3, delta_m, 0.7, 0.0);
  std::printf("Hertz %.6f N; no damping closing %.6f N, opening %.6f N; impact rate 0: %.6f N\n", hertz, elastic,
              elastic_rebound, made_at_rest);
  EXPECT_EQ(elastic, hertz);
  EXPECT_EQ(elastic_rebound, hertz);
  EXPECT_EQ(made_at_rest, hertz);
  EXPECT_EQ(hunt_crossley_damping_factor(1.0), 0.0);  // e = 1: pure Hertz
}

TEST(HuntCrossley, NeverPulls) {
  const double g = 4.2e-8;
  // A factor 1.5 and a rebound 10x faster than the impact: 1 + 1.5 (-10 / 1) = -14 would pull.
  const double rebound = hunt_crossley_force_N(g, 1.5, 9e-5, -10.0, 1.0);
  std::printf("factor 1.5, opening 10x faster than impact: %g N\n", rebound);
  EXPECT_EQ(rebound, 0.0);
  // And nothing without penetration, whatever the rates.
  EXPECT_EQ(hunt_crossley_force_N(g, 1.5, -1e-6, 5.0, 1.0), 0.0);
}

// The damping factor is solved so an isolated impact rebounds at e. Checked
// against what must hold whatever the solver:
// - the round trip e -> alpha -> e;
// - near e = 1 Hunt and Crossley's own first-order alpha = 1.5 (1 - e)
//   (their energy argument; within 2 % at e = 0.99);
// - strong damping: the force vanishes during the rebound where
//   1 + alpha X' = 0 and the bodies part at X' = -1 / alpha: e = 1 / alpha;
// - Hunt and Crossley's alpha = 1.5 at e = 0 rebounds at about 0.49: what
//   the force run measured (a stiff-contact series tending to 1.487 times
//   the plastic jump, README).
TEST(HuntCrossley, TheDampingFactorGivesTheRestitutionAsked) {
  for (const double e : {0.95, 0.7, 0.5, 0.2, 0.05, 0.01, 1e-3, 1e-4}) {
    const double alpha = hunt_crossley_damping_factor(e);
    const double back = hunt_crossley_restitution(alpha);
    std::printf("e %-7g alpha %.8g -> e %.10g; 1 / alpha %.6g; Hunt-Crossley's 1.5 (1 - e) %.6g\n", e, alpha, back,
                1.0 / alpha, 1.5 * (1.0 - e));
    EXPECT_NEAR(back / e, 1.0, 1e-8);  // the bisection's own tolerance, 1e-12 in alpha
  }
  // 1.5 (1 - e) is Hunt and Crossley's first order: 5 % low at e = 0.95, 1 % at 0.99.
  EXPECT_NEAR(hunt_crossley_damping_factor(0.99) / (1.5 * 0.01), 1.0, 0.02);
  EXPECT_NEAR(hunt_crossley_damping_factor(0.01) * 0.01, 1.0, 1e-6);
  const double classic_at_zero = hunt_crossley_restitution(1.5);
  std::printf("Hunt-Crossley's factor at e = 0 rebounds at %.4f\n", classic_at_zero);
  EXPECT_NEAR(classic_at_zero, 0.487, 0.01);
  // Below the smallest resolved restitution, that one.
  EXPECT_EQ(hunt_crossley_damping_factor(0.0), hunt_crossley_damping_factor(kSmallestRestitution));
}

}  // namespace
}  // namespace railjoint
