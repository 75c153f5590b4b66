// The anomaly measures of one crossing, on hand-made trajectories of a
// scenario-1 crossing whose exact path is known in closed form.
//
// Scenario 1 (theta = 30 deg, beta = 0.03 rad, y_w = 2 mm < y_t = 4.11 mm,
// a 1 mm wide cylinder that overlaps the band |y| <= y_t): the wheel touches
// the plane z = -tan(beta/2) x before the V bottom and z = +tan(beta/2) x
// after it, so its centre, R along the plane normal, runs on
//   z_c(x) = |x| tan(beta/2) + R / cos(beta/2),
// with zdot = v sign(x) tan(beta/2); the jump in zdot is 2 v tan(beta/2) =
// 2 * 50 * tan(0.015) = 1.50011251 m/s, at x = 0.

#include <cmath>
#include <iostream>
#include <limits>
#include <numbers>

#include <gtest/gtest.h>

#include "models/impact_prediction.h"
#include "scenes/studies/crossing_diagnostics.h"

namespace railjoint {
namespace {

constexpr double kBeta = 0.03;
constexpr double kV = 50.0;
constexpr double kR = 0.475;

struct Fixture {
  JointParams joint;
  SimulationResult result;
};

Fixture on_the_path() {
  Fixture f;
  f.joint.theta_rad = std::numbers::pi / 6.0;
  f.joint.beta_rad = kBeta;
  WheelParams wheel;
  wheel.lateral_m = 0.002;
  wheel.width_m = 1e-3;
  auto model = std::make_shared<CrossingModel>();
  model->joint = f.joint;
  model->wheel = wheel;
  model->simulated_wheel = wheel;
  model->prediction = predict_impact(f.joint, wheel);
  f.result.model = model;
  RigidJump jump;
  jump.struck_point_m = model->prediction.contact_A_m;  // measured, so finite
  // 0.1 % above the exact jump.
  jump.jump_Ns = 1.001 * model->prediction.impulse.exact_Ns;
  f.result.impact = jump;
  const double t = std::tan(kBeta / 2.0);
  // Centre x from -49.5 mm to +49.5 mm in 1 mm steps (never exactly on the kink).
  for (int i = 0; i < 100; ++i) {
    const double x = -0.0495 + 1e-3 * i;
    WheelSample s;
    s.time_s = (x + 0.05) / kV;
    s.centre_m = {x, wheel.lateral_m, std::abs(x) * t + kR / std::cos(kBeta / 2.0)};
    s.velocity_m_per_s = {kV, 0.0, (x < 0 ? -1.0 : 1.0) * kV * t};
    ContactSample c;
    c.distance_m = -4e-6;
    s.contacts.push_back(c);
    f.result.trajectory.samples.push_back(s);
  }
  return f;
}

TEST(CrossingDiagnostics, ATrajectoryOnTheKinematicPathHasNoAnomaly) {
  const Fixture f = on_the_path();
  ASSERT_EQ(f.result.prediction().scenario, ImpactScenario::one);
  const CrossingDiagnostics d = diagnose_crossing(f.joint, f.result);
  std::cout << "sink " << d.max_sink_m << " m, zdot deviation " << d.approach_zdot_deviation_m_per_s << " m/s, error "
            << d.relative_error << "\n";
  EXPECT_FALSE(d.non_finite);
  EXPECT_FALSE(d.tunnelled);
  EXPECT_FALSE(d.passed_without_impact);
  // The hand formula and the model's path agree to round-off (1e-12 m on ~0.5 m).
  EXPECT_LT(d.max_sink_m, 1e-12);
  EXPECT_LT(d.approach_zdot_deviation_m_per_s, 1e-12);
  EXPECT_EQ(d.approach_speed_drift, 0.0);
  EXPECT_NEAR(d.relative_error, 1e-3, 1e-12);
  // x <= -0.2 mm: the 50 samples from -49.5 to -0.5 mm.
  EXPECT_EQ(d.approach_samples, 50);
}

TEST(CrossingDiagnostics, DriftOverTheApproachIsMeasuredAgainstTheJump) {
  Fixture f = on_the_path();
  f.result.trajectory.samples[10].velocity_m_per_s.z() += 0.003;
  f.result.trajectory.samples[20].velocity_m_per_s.x() += 1e-3;
  const CrossingDiagnostics d = diagnose_crossing(f.joint, f.result);
  std::cout << "zdot drift " << d.approach_zdot_drift << ", speed drift " << d.approach_speed_drift << "\n";
  EXPECT_NEAR(d.approach_zdot_deviation_m_per_s, 0.003, 1e-12);
  // 0.003 / (2 * 50 * tan(0.015)) = 0.003 / 1.50011251 = 1.99985e-3.
  EXPECT_NEAR(d.approach_zdot_drift, 0.003 / 1.50011251, 1e-9);
  EXPECT_NEAR(d.approach_speed_drift, 1e-3 / kV, 1e-15);
}

TEST(CrossingDiagnostics, AWheelBelowTheOutgoingPathTunnelled) {
  Fixture f = on_the_path();
  for (WheelSample& s : f.result.trajectory.samples) {
    if (s.centre_m.x() > 0.01) s.centre_m.z() -= 1e-3;  // 1 mm into the outgoing rail
  }
  f.result.impact.reset();
  const CrossingDiagnostics d = diagnose_crossing(f.joint, f.result);
  EXPECT_NEAR(d.max_sink_m, 1e-3, 1e-12);
  EXPECT_TRUE(d.tunnelled);
  EXPECT_TRUE(d.passed_without_impact);
  EXPECT_TRUE(std::isnan(d.relative_error));
}

TEST(CrossingDiagnostics, FindsNaNInAContact) {
  Fixture f = on_the_path();
  f.result.trajectory.samples[42].contacts[0].distance_m = std::numeric_limits<double>::quiet_NaN();
  const CrossingDiagnostics d = diagnose_crossing(f.joint, f.result);
  EXPECT_TRUE(d.non_finite);
  EXPECT_EQ(d.non_finite_where, "sample 42 contact");
}

TEST(CrossingDiagnostics, FindsInfInTheVelocity) {
  Fixture f = on_the_path();
  f.result.trajectory.samples[70].velocity_m_per_s.z() = std::numeric_limits<double>::infinity();
  const CrossingDiagnostics d = diagnose_crossing(f.joint, f.result);
  EXPECT_TRUE(d.non_finite);
  EXPECT_EQ(d.non_finite_where, "sample 70 velocity");
}

}  // namespace
}  // namespace railjoint
