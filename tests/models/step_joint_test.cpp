// The step-up worked example of thesis section 3.2.2 / figure 3.7:
// u0 = 0.3 m, R = 1 m, M = 750 kg, v = 50 m/s.
//
// Hand derivation (cos(alpha) = (R - u0)/R, sin(alpha) = a/R):
//   a       = sqrt(2 R u0 - u0^2) = sqrt(0.6 - 0.09) = sqrt(0.51) = 0.714142842854285 m
//   alpha   = acos(0.7) = 0.795398830184144 rad
//   exact   zdot+ = v tan(alpha) = 50 * 0.714142842854285 / 0.7 = 51.0102030610203 m/s
//           Delta p = 750 * 51.0102030610203 = 38257.6522957653 N s
//   thesis  eq. 3.6: v sqrt(2 R u0) / sqrt(R^2 - 2 R u0) = 50 sqrt(0.6/0.4) = 61.2372435695795 m/s
//           Delta p = 45927.9326771846 N s
//   R >> u0 eq. 3.6: v sqrt(2 u0 / R) = 50 sqrt(0.6) = 38.7298334620742 m/s -> 29047.3750965556 N s

#include <cmath>
#include <iostream>
#include <string>

#include <gtest/gtest.h>

#include "models/impact_prediction.h"
#include "models/step_joint.h"
#include "support/input_error.h"

namespace railjoint {
namespace {

constexpr double kR = 1.0;
constexpr double kU0 = 0.3;
constexpr double kV = 50.0;
constexpr double kM = 750.0;
// Hand values are given to 15 significant digits; the code evaluates the same
// closed forms in double, so agreement to 1e-12 relative is expected.
constexpr double kRelTol = 1e-12;

JointParams figure_3_7_joint(double u0) {
  JointParams joint;
  joint.kind = JointKind::step;
  joint.step_height_m = u0;
  joint.length_m = 4.0;  // the rails must hold a 1 m wheel on both sides
  return joint;
}

WheelParams figure_3_7_wheel() {
  WheelParams wheel;
  wheel.radius_m = kR;
  wheel.mass_kg = kM;
  wheel.speed_m_per_s = kV;
  wheel.lateral_m = 0.0;
  return wheel;
}

TEST(StepJoint, EdgeDistanceOfFigure37ForLargeR) {
  // sqrt(2 R u0) = sqrt(0.6); the exact a = sqrt(0.51) is the profile solve's x_A (below).
  EXPECT_NEAR(step_edge_distance_large_R_m(kR, kU0), std::sqrt(0.6), 1e-14);
}

TEST(StepJoint, ThreeFormsOfTheJump) {
  const ImpactPrediction p = predict_impact(figure_3_7_joint(kU0), figure_3_7_wheel());
  std::cout << "exact " << p.impulse.exact_Ns << " thesis " << p.impulse.thesis_Ns << " small "
            << p.impulse.small_angle_Ns << " N s\n";
  EXPECT_EQ(p.scenario, ImpactScenario::step);
  EXPECT_FALSE(p.on_landing);
  // The exact value comes from the profile solve (bisection), not the closed form:
  // its agreement is limited by the bisection's round-off in x (~1e-16 m) times the
  // curvature 1/R near the contact; 1e-9 relative is far above that.
  EXPECT_NEAR(p.impulse.exact_Ns, 38257.6522957653, 38257.65 * 1e-9);
  EXPECT_NEAR(p.impulse.thesis_Ns, 45927.9326771846, 45927.93 * kRelTol);
  EXPECT_NEAR(p.impulse.small_angle_Ns, 29047.3750965556, 29047.38 * kRelTol);
  EXPECT_NEAR(p.x_A_m, 0.714142842854285, 1e-9);
  // The wheel centre is a behind the edge at x = 0, at height R above the approach.
  EXPECT_NEAR(p.impact_wheel_x_m, -0.714142842854285, 1e-9);
  EXPECT_NEAR(p.impact_wheel_z_m, kR, 1e-12);
}

TEST(StepJoint, StepDownIsTheTimeReverseOfStepUp) {
  const ImpactPrediction up = predict_impact(figure_3_7_joint(kU0), figure_3_7_wheel());
  const ImpactPrediction down = predict_impact(figure_3_7_joint(-kU0), figure_3_7_wheel());
  EXPECT_TRUE(down.on_landing);
  EXPECT_NEAR(down.impulse.exact_Ns, up.impulse.exact_Ns, up.impulse.exact_Ns * 1e-9);
  // Mirrored: the wheel lands a ahead of the edge.
  EXPECT_NEAR(down.impact_wheel_x_m, 0.714142842854285, 1e-9);
  EXPECT_NEAR(down.zdot_before_m_per_s, -51.0102030610203, 1e-7);
  EXPECT_NEAR(down.zdot_after_m_per_s, 0.0, 1e-12);
}

// With an end-post gap g the incoming rail ends at -g/2 and the raised rail
// starts at +g/2. The wheel, resting on the flat, meets the raised corner when
// its centre is a = sqrt(2 R u0 - u0^2) behind it, at x = g/2 - a; it is still
// on the incoming top there (contact below the centre, x <= -g/2) only while
// g <= a = 0.714142842854285 m. A step down is the mirror image (it lands a
// past the edge, on the lower top only while g <= a). Wider gaps: the wheel
// drops into the gap first (the general model, models/wheel_rail_envelope.h).
TEST(StepJoint, AGapWiderThanTheContactDistanceDropsTheWheelOntoBothCorners) {
  // Up to the contact distance a the wheel still rests on the near rail's
  // top when it meets the far rail's corner; beyond, it pivots over the near
  // corner into the gap first and strikes from there: both contacts on the
  // corners (-+g/2), and the jump goes on continuously through g = a (both
  // answers are the same crossing there).
  constexpr double kA = 0.714142842854285;
  for (const double u0 : {kU0, -kU0}) {
    JointParams joint = figure_3_7_joint(u0);
    joint.gap_m = 0.999999 * kA;
    const double bridged = predict_impact(joint, figure_3_7_wheel()).impulse.exact_Ns;
    joint.gap_m = 1.000001 * kA;
    const ImpactPrediction dropped = predict_impact(joint, figure_3_7_wheel());
    EXPECT_NEAR(dropped.impulse.exact_Ns, bridged, 1e-4 * bridged) << u0;
    joint.gap_m = 1.2 * kA;
    const ImpactPrediction wide = predict_impact(joint, figure_3_7_wheel());
    EXPECT_NEAR(std::abs(wide.contact_A_m.x()), 0.6 * kA, 1e-12) << u0;
    EXPECT_NEAR(std::abs(wide.contact_B_m.x()), 0.6 * kA, 1e-12) << u0;
    EXPECT_GT(wide.impulse.exact_Ns, 0.0) << u0;
  }
}

TEST(StepJoint, ALevelStepHasNoJump) {
  const ImpactPrediction p = predict_impact(figure_3_7_joint(0.0), figure_3_7_wheel());
  EXPECT_EQ(p.impulse.exact_Ns, 0.0);
  EXPECT_EQ(p.impulse.thesis_Ns, 0.0);
  EXPECT_EQ(p.impulse.small_angle_Ns, 0.0);
}

TEST(StepJoint, SmallStepFormsConvergeAsU0OverRVanishes) {
  // All three forms share the leading term v sqrt(2 u0 / R); their relative
  // differences are O(u0 / R): exact/small - 1 = 3/4 xi + 0.72 xi^2 + ..., thesis/small - 1 = xi + 1.5 xi^2 + ... (xi = u0/R).
  for (double u0 : {1e-3, 1e-4, 1e-5}) {
    JointParams joint = figure_3_7_joint(u0);
    WheelParams wheel = figure_3_7_wheel();
    const ImpactPrediction p = predict_impact(joint, wheel);
    const double xi = u0 / kR;
    EXPECT_NEAR(p.impulse.exact_Ns / p.impulse.small_angle_Ns - 1.0, 0.75 * xi, 1.0 * xi * xi + 1e-9) << "u0 " << u0;
    EXPECT_NEAR(p.impulse.thesis_Ns / p.impulse.small_angle_Ns - 1.0, xi, 2.0 * xi * xi + 1e-12) << "u0 " << u0;
  }
}

}  // namespace
}  // namespace railjoint
