// Time histories around the impact (figures 3.7 and 4.5).

#include <cmath>

#include <gtest/gtest.h>

#include "models/impact_prediction.h"
#include "models/time_history.h"

namespace railjoint {
namespace {

std::size_t first_after_zero(const TimeHistory& h) {
  std::size_t i = 0;
  while (h.time_s[i] <= 0.0) ++i;
  return i;
}

TEST(TimeHistory, ScenarioOneIsTwoStraightLines) {
  WheelParams wheel;
  wheel.lateral_m = 0.002;
  const TimeHistory h = impact_time_history(JointParams{}, wheel, 2e-4, 2e-4, 401);
  const double t = std::tan(0.015);
  for (std::size_t i = 0; i < h.time_s.size(); ++i) {
    const double expected = h.time_s[i] > 0 ? t * 50 * h.time_s[i] : -t * 50 * h.time_s[i];
    EXPECT_NEAR(h.z_exact_m[i], expected, 1e-15) << i;
    EXPECT_NEAR(h.zdot_exact_m_per_s[i], h.time_s[i] > 0 ? 50 * t : -50 * t, 1e-12) << i;
    EXPECT_NEAR(h.zdot_linear_m_per_s[i], h.time_s[i] > 0 ? 50 * std::sin(0.015) : -50 * std::sin(0.015), 1e-12);
  }
  // The thesis's impulse trace is a single spike of the jump's size at t = 0.
  const std::size_t i = first_after_zero(h);
  EXPECT_NEAR(h.impulse_exact_Ns[i], 2 * 750 * 50 * t, 1e-9);
  EXPECT_NEAR(h.impulse_exact_Ns[i + 1], 0.0, 1e-9);
}

TEST(TimeHistory, ScenarioTwoPivotsAboutTheCorner) {
  const JointParams joint;  // figure 4.5, theta = 30 deg
  const WheelParams wheel;  // y_w = 15 mm
  const ImpactPrediction p = predict_impact(joint, wheel);
  const double pivot_end_s = (p.x_A_m - 0.475 * std::sin(0.015)) / 50.0;
  const TimeHistory h = impact_time_history(joint, wheel, 1e-4, pivot_end_s, 1001);
  // Every sample after the impact keeps the centre at R from the corner A.
  for (std::size_t i = first_after_zero(h); i + 1 < h.time_s.size(); ++i) {
    const double x = p.impact_wheel_x_m + 50.0 * h.time_s[i];
    const double z = p.impact_wheel_z_m + h.z_exact_m[i];
    EXPECT_NEAR(std::hypot(x - p.contact_A_m.x(), z - p.contact_A_m.z()), 0.475, 1e-12) << i;
  }
  // Right after the impact zdot = v tan(alpha); the first sample lies dt into the
  // pivot, where the centre on a circle of radius R at speed ~v has lost at most
  // ~v^2/R * dt / cos^3(alpha) (cos^3 > 0.997 here; factor 1.1 for margin).
  const std::size_t i = first_after_zero(h);
  const double curvature_loss = 1.1 * 50.0 * 50.0 / 0.475 * h.time_s[i];
  EXPECT_LT(h.zdot_exact_m_per_s[i], 50 * std::tan(p.alpha_rad));
  EXPECT_GT(h.zdot_exact_m_per_s[i], 50 * std::tan(p.alpha_rad) - curvature_loss);
  EXPECT_NEAR(h.zdot_exact_m_per_s.back(), 50 * std::tan(0.015), 1e-6);
  // The linearised path leaves at sin(alpha_thesis) v.
  EXPECT_NEAR(h.zdot_linear_m_per_s.back(), 50 * std::sin(p.alpha_thesis_rad), 1e-12);
}

TEST(TimeHistory, Figure37StepReturnsToTheTopAtT1) {
  JointParams joint;
  joint.kind = JointKind::step;
  joint.step_height_m = 0.3;
  joint.length_m = 4.0;
  WheelParams wheel;
  wheel.radius_m = 1.0;
  wheel.lateral_m = 0.0;
  const double t1 = 0.0142828568570857;  // a / v, see step_joint_test.cpp
  const TimeHistory h = impact_time_history(joint, wheel, 0.005, t1, 2001);
  EXPECT_NEAR(h.z_exact_m.back(), 0.3, 1e-9);
  EXPECT_NEAR(h.z_exact_m.front(), 0.0, 1e-15);
  EXPECT_NEAR(h.zdot_exact_m_per_s[first_after_zero(h)], 51.0102030610203, 0.05)
      << "one sample (7 us) into the pivot the speed has fallen by ~zddot*dt";
}

}  // namespace
}  // namespace railjoint
