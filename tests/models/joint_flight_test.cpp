// The flight at the joint against hand derivations on a step joint, where
// the rails are level lines and the flight is a parabola between them.

#include "models/joint_flight.h"

#include <cmath>
#include <iostream>

#include <gtest/gtest.h>

#include "models/impact_prediction.h"

namespace railjoint {
namespace {

constexpr double kR_m = 0.475;
constexpr double kM_kg = 750.0;
constexpr double kW_N = 112.5e3 + kM_kg * 9.81;  // axle load share + weight

JointParams step(double u0_m) {
  JointParams joint;
  joint.kind = JointKind::step;
  joint.step_height_m = u0_m;
  return joint;
}

WheelParams wheel_at(double speed_m_per_s) {
  WheelParams wheel;
  wheel.radius_m = kR_m;
  wheel.mass_kg = kM_kg;
  wheel.lateral_m = 0.0;
  wheel.speed_m_per_s = speed_m_per_s;
  return wheel;
}

TEST(JointFlight, StepUpFliesFromTheStrikeUntilItIsBackOnTheUpperRail) {
  // Step up u0 = 5 mm: the wheel strikes the corner (0, u0) with its centre
  // at x = -sqrt(2 R u0 - u0^2), z = R, radius angle alpha from the vertical,
  // cos(alpha) = (R - u0) / R; the pivot leaves at once when
  // v > v_c = sqrt(W R cos^3(alpha) / M) = 8.3 m/s. At 30 m/s it flies with
  // zdot = v tan(alpha) under g = W / M and lands on the upper rail's centre
  // line z = R + u0, u0 above the lift-off point:
  //   v tan(alpha) t - g t^2 / 2 = u0  (the later root).
  const double u0 = 0.005, v = 30.0;
  const JointParams joint = step(u0);
  const WheelParams wheel = wheel_at(v);
  const double cos_a = (kR_m - u0) / kR_m;
  const double tan_a = std::sqrt(1.0 - cos_a * cos_a) / cos_a;
  const double g = kW_N / kM_kg;
  const double w0 = v * tan_a;
  const double t = (w0 + std::sqrt(w0 * w0 - 2.0 * g * u0)) / g;
  const JointFlight f = predict_joint_flight(joint, wheel, predict_impact(joint, wheel), kW_N);
  std::cout << "flight " << f.duration_s * 1e3 << " ms (hand " << t * 1e3 << " ms), from x " << f.liftoff_x_m * 1e3
            << " mm to " << f.landing_x_m * 1e3 << " mm\n";
  ASSERT_TRUE(f.flies);
  EXPECT_NEAR(f.liftoff_x_m, -std::sqrt(2.0 * kR_m * u0 - u0 * u0), 1e-12);
  // The landing is bisected to round-off on the path the model solves to ~1e-12 m.
  EXPECT_NEAR(f.duration_s, t, 1e-9);
  EXPECT_NEAR(f.apex_height_m, w0 * w0 / (2.0 * g), 1e-12);

  // Below v_c it follows the corner: no flight.
  const double v_c = std::sqrt(kW_N * kR_m * cos_a * cos_a * cos_a / kM_kg);
  const WheelParams slow = wheel_at(0.99 * v_c);
  EXPECT_FALSE(predict_joint_flight(joint, slow, predict_impact(joint, slow), kW_N).flies);
  const WheelParams fast = wheel_at(1.01 * v_c);
  EXPECT_TRUE(predict_joint_flight(joint, fast, predict_impact(joint, fast), kW_N).flies);
}

TEST(JointFlight, StepDownLeavesTheEdgeAtTheTopWhenTheLoadCannotBendThePath) {
  // Step down |u0| = 5 mm at 50 m/s: v^2 / R = 5263 m/s^2 > g = 160 m/s^2,
  // so even the top of the arc (phi = 0, level approach) cannot be followed:
  // the wheel leaves the edge (0, 0) level at z = R and falls to the lower
  // rail's centre line z = R - |u0|: t = sqrt(2 |u0| / g), landing at v t.
  const double u0 = -0.005, v = 50.0;
  const JointParams joint = step(u0);
  const WheelParams wheel = wheel_at(v);
  const double g = kW_N / kM_kg;
  const double t = std::sqrt(2.0 * -u0 / g);
  const JointFlight f = predict_joint_flight(joint, wheel, predict_impact(joint, wheel), kW_N);
  std::cout << "flight " << f.duration_s * 1e3 << " ms (hand " << t * 1e3 << " ms), lands at " << f.landing_x_m
            << " m\n";
  ASSERT_TRUE(f.flies);
  EXPECT_NEAR(f.liftoff_x_m, 0.0, 1e-12);
  EXPECT_NEAR(f.duration_s, t, 1e-9);
  EXPECT_NEAR(f.landing_x_m, v * t, 1e-7);
}

TEST(JointFlight, StepDownFollowsTheEdgeUntilTheLoadNoLongerSuffices) {
  // At a speed where the top of the arc holds (v^2 / R < g) the wheel rolls
  // over the edge until cos^3(phi) = M v^2 / (W R), then leaves with the
  // arc's velocity -v tan(phi) from C = (R sin phi, R cos phi). With
  // |u0| = 40 mm the landing angle asin(sqrt(2 R |u0| - u0^2) / R) = 0.40 rad
  // lies beyond that angle at 8 m/s (0.334 rad; v^2 / R = 135 m/s^2 < g = 160 m/s^2), so it flies.
  const double u0 = -0.040, v = 8.0;
  const JointParams joint = step(u0);
  const WheelParams wheel = wheel_at(v);
  const double g = kW_N / kM_kg;
  const double phi = std::acos(std::cbrt(kM_kg * v * v / (kW_N * kR_m)));
  const double phi_land = std::asin(std::sqrt(2.0 * kR_m * -u0 - u0 * u0) / kR_m);
  ASSERT_LT(phi, phi_land);
  // Fall from z0 = R cos(phi) with w0 = -v tan(phi) to z = R + u0:
  //   w0 t - g t^2 / 2 = (R + u0) - R cos(phi).
  const double w0 = -v * std::tan(phi);
  const double drop = kR_m * std::cos(phi) - (kR_m + u0);
  const double t = (w0 + std::sqrt(w0 * w0 + 2.0 * g * drop)) / g;
  const JointFlight f = predict_joint_flight(joint, wheel, predict_impact(joint, wheel), kW_N);
  std::cout << "leaves at phi " << phi << " rad, flight " << f.duration_s * 1e3 << " ms (hand " << t * 1e3
            << " ms)\n";
  ASSERT_TRUE(f.flies);
  EXPECT_NEAR(f.liftoff_x_m, kR_m * std::sin(phi), 1e-12);
  EXPECT_NEAR(f.duration_s, t, 1e-9);
}

TEST(JointFlight, TheVHasNoCornerToFlyFrom) {
  JointParams joint;
  joint.theta_rad = 45.0 * 3.14159265358979323846 / 180.0;
  WheelParams wheel = wheel_at(50.0);
  wheel.lateral_m = 0.002;  // scenario 1 at 45 deg (y_t = 7.1 mm)
  const ImpactPrediction p = predict_impact(joint, wheel);
  ASSERT_EQ(p.scenario, ImpactScenario::one);
  EXPECT_FALSE(predict_joint_flight(joint, wheel, p, kW_N).flies);
}

}  // namespace
}  // namespace railjoint
