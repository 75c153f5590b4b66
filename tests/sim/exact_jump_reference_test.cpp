// The test-side exact reference (exact_jump_reference.h) against hand
// derivations, and against models/'s slice-profile solve, an independent
// route to the same jump.

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "models/impact_prediction.h"
#include "tests/sim/exact_jump_reference.h"
#include "tests/sim/random_scenes.h"

namespace railjoint::testing_reference {
namespace {

JointParams inclined(double theta_deg, double beta_rad) {
  JointParams j;
  j.theta_rad = theta_deg * std::numbers::pi / 180.0;
  j.beta_rad = beta_rad;
  return j;
}

TEST(ExactJumpReference, ScenarioOneIsTwiceTheSlope) {
  // y_w = 2 mm < y_t = R sin(beta/2) tan(45 deg) = 7.12 mm: the V, slopes -tan(beta/2) then +tan(beta/2).
  WheelParams w;
  w.lateral_m = 0.002;
  const ExactJump e = exact_jump(inclined(45, 0.03), w);
  EXPECT_NEAR(e.jump_Ns, 2 * 750 * 50 * std::tan(0.015), 1e-9);
  EXPECT_NEAR(e.impact_x_m, 0.0, 1e-12);
  EXPECT_FALSE(e.on_landing);
}

TEST(ExactJumpReference, StepUpAndDownAreMvTanAlpha) {
  // cos(alpha) = (R - |u0|) / R = 0.474 / 0.475; tan(alpha) = 0.0649912312268.
  JointParams j;
  j.kind = JointKind::step;
  WheelParams w;
  w.lateral_m = 0;
  for (const double u0 : {0.001, -0.001}) {
    j.step_height_m = u0;
    const ExactJump e = exact_jump(j, w);
    EXPECT_NEAR(e.jump_Ns, 750 * 50 * 0.0649912312268, 1e-6) << u0;
    EXPECT_EQ(e.on_landing, u0 < 0);
    // Struck at the step edge R sin(alpha) = sqrt(R^2 - (R - u0)^2) = sqrt(0.000949) m ahead of the
    // centre; the landing as far past the edge it rolled off.
    EXPECT_NEAR(e.impact_x_m, (u0 > 0 ? -1 : 1) * std::sqrt(0.000949), 1e-12) << u0;
  }
}

TEST(ExactJumpReference, ThinDiscScenarioTwoStrikesTheCutEdge) {
  // Scenario 2 at theta 30 deg, y 15 mm: the edge at x_cut = y cot(theta) =
  // 25.98 mm is x_A = R sin(alpha) ahead of the centre, and the centre lies on
  // the incoming rail's offset line: -t x* + R/cos(beta/2) = t x_cut + R cos(alpha).
  WheelParams w;
  const JointParams j = inclined(30, 0.03);
  const ExactJump e = exact_jump(j, w);
  const double t = std::tan(0.015);
  const double alpha = std::asin((e.struck_x_m - e.impact_x_m) / w.radius_m);
  EXPECT_NEAR(e.struck_x_m, 0.015 / std::tan(j.theta_rad), 1e-12);
  EXPECT_NEAR(-t * e.impact_x_m + w.radius_m / std::cos(0.015), t * e.struck_x_m + w.radius_m * std::cos(alpha), 1e-12);
  EXPECT_NEAR(e.jump_Ns, 750 * 50 * (std::tan(alpha) + t), 1e-6);
}

TEST(ExactJumpReference, MirroredWheelJumpsAsHardOnLanding) {
  // Without inertia the step-down side is the time reverse of the mirrored step
  // up (models/DESIGN.md "Three forms of every analytic impulse").
  WheelParams up, down;
  up.lateral_m = 0.012;
  down.lateral_m = -0.012;
  const JointParams j = inclined(40, 0.04);
  const ExactJump a = exact_jump(j, up), b = exact_jump(j, down);
  EXPECT_TRUE(b.on_landing);
  EXPECT_NEAR(a.jump_Ns, b.jump_Ns, 1e-9 * a.jump_Ns);
}

TEST(ExactJumpReference, AgreesWithTheModelsSliceSolveOnRandomCrossings) {
  // Two independent routes (models/ solves each slice's two-point contact).
  // Agreement to 1e-9 relative: both are solves to round-off.
  int compared = 0;
  for (const RandomCrossing& c : random_crossings(300, 7)) {
    ImpactPrediction p;
    try {
      p = predict_impact(c.joint, c.wheel);
    } catch (const std::exception&) {
      continue;  // outside the model (a gap with a finite width, ...): the simulation refuses these too
    }
    const ExactJump e = exact_jump(c.joint, c.wheel);
    EXPECT_NEAR(e.jump_Ns, p.impulse.exact_Ns, 1e-9 * std::abs(p.impulse.exact_Ns)) << c.name;
    ++compared;
  }
  EXPECT_GT(compared, 200);
}

}  // namespace
}  // namespace railjoint::testing_reference
