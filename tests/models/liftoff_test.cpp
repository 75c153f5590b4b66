// The pivot lift-off speed and the ballistic flight after it (models/liftoff.h),
// checked against hand values and against the kinematics of the arc and the
// flight integrated numerically here (never with the formulas under test).

#include "models/liftoff.h"

#include <cmath>
#include <iostream>

#include <gtest/gtest.h>

namespace railjoint {
namespace {

// Thesis parameters: M = 750 kg, R = 0.475 m, static wheel load 112.5 kN
// (thesis table 6.1) on top of the wheel's weight: W = 750 * 9.81 + 112500 = 119857.5 N.
constexpr double kMass_kg = 750.0;
constexpr double kRadius_m = 0.475;
constexpr double kLoad_N = 750.0 * 9.81 + 112.5e3;

TEST(PivotLiftoff, FlatGroundValueIsTheClassicOne) {
  // phi = 0: the wheel on top of the corner, v_c^2 / R = W / M:
  // v_c = sqrt(119857.5 * 0.475 / 750) = 8.712620156990663 m/s (hand, python).
  const double v_c = pivot_liftoff_speed_m_per_s(kMass_kg, kRadius_m, kLoad_N, 0.0);
  std::cout << "v_c(phi = 0) = " << v_c << " m/s\n";
  EXPECT_NEAR(v_c, 8.712620156990663, 1e-12);
  // N = W - M v^2 / R at phi = 0: at 5 m/s, 119857.5 - 750 * 25 / 0.475 = 80384.8684 N.
  EXPECT_NEAR(pivot_contact_force_N(kMass_kg, kRadius_m, kLoad_N, 5.0, 0.0), 119857.5 - 750.0 * 25.0 / 0.475, 1e-8);
}

TEST(PivotLiftoff, ContactForceVanishesAtTheLiftoffSpeed) {
  for (const double phi : {0.015, 0.0414, 0.1, -0.0414}) {
    const double v_c = pivot_liftoff_speed_m_per_s(kMass_kg, kRadius_m, kLoad_N, phi);
    const double n = pivot_contact_force_N(kMass_kg, kRadius_m, kLoad_N, v_c, phi);
    std::cout << "phi " << phi << ": v_c " << v_c << " m/s, N(v_c) " << n << " N\n";
    // Round-off on a 1.2e5 N balance: 1e-9 of it.
    EXPECT_NEAR(n, 0.0, 1e-9 * kLoad_N);
    EXPECT_GT(pivot_contact_force_N(kMass_kg, kRadius_m, kLoad_N, 0.99 * v_c, phi), 0.0);
    EXPECT_LT(pivot_contact_force_N(kMass_kg, kRadius_m, kLoad_N, 1.01 * v_c, phi), 0.0);
    // The load that just holds the wheel at v_c is W again.
    EXPECT_NEAR(pivot_following_load_N(kMass_kg, kRadius_m, v_c, phi), kLoad_N, 1e-9 * kLoad_N);
  }
}

TEST(PivotLiftoff, ContactForceMatchesTheArcKinematicsDifferentiatedNumerically) {
  // Independent route: the centre on the arc about the corner at the origin,
  // z(x) = sqrt(R^2 - x^2), moving at xdot = v, so zddot = v^2 z''(x); the
  // vertical balance M zddot = N cos(phi) - W gives N. z'' by central
  // differences with h = 1e-5 m: truncation ~ h^2 z''''/12 ~ 1e-10 relative,
  // round-off ~ eps z / h^2 ~ 1e-6 of z'' = 1/R: tolerance 1e-5 of W.
  const double v = 30.0;
  for (const double phi : {0.0, 0.02, 0.05, -0.05}) {
    const double x = kRadius_m * std::sin(phi);
    const auto z = [](double xx) { return std::sqrt(kRadius_m * kRadius_m - xx * xx); };
    const double h = 1e-5;
    const double z2 = (z(x + h) - 2.0 * z(x) + z(x - h)) / (h * h);
    const double n_numeric = (kMass_kg * v * v * z2 + kLoad_N) / std::cos(phi);
    const double n = pivot_contact_force_N(kMass_kg, kRadius_m, kLoad_N, v, phi);
    std::cout << "phi " << phi << ": N " << n << " N, from the arc " << n_numeric << " N\n";
    EXPECT_NEAR(n, n_numeric, 1e-5 * kLoad_N);
  }
}

TEST(PivotLiftoff, SteeperRadiusLowersTheLiftoffSpeed) {
  // v_c(phi) / v_c(0) = cos(phi)^1.5: at alpha = 0.0414 rad (scenario 2 at
  // theta = 30 deg, y_w = 15 mm), 0.998715...
  const double ratio = pivot_liftoff_speed_m_per_s(kMass_kg, kRadius_m, kLoad_N, 0.0414) /
                       pivot_liftoff_speed_m_per_s(kMass_kg, kRadius_m, kLoad_N, 0.0);
  EXPECT_NEAR(ratio, std::pow(std::cos(0.0414), 1.5), 1e-14);
  EXPECT_LT(ratio, 1.0);
}

TEST(BallisticFlight, HandValues) {
  // w0 = 2 m/s, g_eff = 160 m/s^2, v = 50 m/s, landing line 1 mm above the
  // lift-off point rising at 0.015: w' = 2 - 0.75 = 1.25 m/s,
  // t = (1.25 + sqrt(1.25^2 - 2 * 160 * 0.001)) / 160 = 0.014779217753002486 s,
  // apex 2^2 / (2 * 160) = 0.0125 m at 2 / 160 = 0.0125 s.
  const BallisticFlight f = ballistic_flight(2.0, 160.0, 50.0, 0.001, 0.015);
  std::cout << "flight " << f.flight_time_s << " s, apex " << f.apex_height_m << " m\n";
  EXPECT_NEAR(f.flight_time_s, 0.014779217753002486, 1e-15);
  EXPECT_NEAR(f.apex_height_m, 0.0125, 1e-15);
  EXPECT_NEAR(f.apex_time_s, 0.0125, 1e-15);
  EXPECT_NEAR(f.landing_zdot_m_per_s, 2.0 - 160.0 * 0.014779217753002486, 1e-12);
}

TEST(BallisticFlight, MatchesAStepByStepIntegration) {
  // Integrate z'' = -g_eff with tiny steps and find when z meets the line:
  // independent of the quadratic formula. dt = 1e-7 s: the landing is found to
  // within one step (1e-7 s), and the explicit position update is exact for
  // constant acceleration.
  const double w0 = 1.3, g = 200.0, v = 20.0, gap = 2e-4, slope = 0.015;
  double t = 0.0, z = 0.0, w = w0;
  const double dt = 1e-7;
  bool left = false;
  while (t < 1.0) {
    z += w * dt - 0.5 * g * dt * dt;
    w -= g * dt;
    t += dt;
    const double above = z - (gap + slope * v * t);
    if (above > 0.0) left = true;
    if (left && above <= 0.0) break;
  }
  const BallisticFlight f = ballistic_flight(w0, g, v, gap, slope);
  std::cout << "integrated landing " << t << " s, formula " << f.flight_time_s << " s\n";
  EXPECT_NEAR(f.flight_time_s, t, 2e-7);
}

TEST(BallisticFlight, NoLandingWhenTheLineIsOutOfReach) {
  // The centre never climbs 1 m at 1 m/s under 10 m/s^2 (apex 5 cm).
  EXPECT_TRUE(std::isnan(ballistic_flight(1.0, 10.0, 0.0, 1.0, 0.0).flight_time_s));
}

}  // namespace
}  // namespace railjoint
