// A finite-width wheel (thesis section 3.3.5, figure 3.21). At theta = 30 deg,
// beta = 0.03: y_t = 0.475 sin(0.015) tan(30 deg) = 4.11346 mm.

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "models/finite_width_wheel.h"
#include "models/impact_prediction.h"
#include "models/inclined_joint.h"

namespace railjoint {
namespace {

const JointParams kJoint{};  // theta 30 deg, beta 0.03, b_t 20 mm
const double kYt = transition_y_m(kJoint, 0.475);

WheelParams cylinder(double y_m, double width_m) {
  WheelParams wheel;
  wheel.lateral_m = y_m;
  wheel.width_m = width_m;
  return wheel;
}

TEST(FiniteWidthWheel, TransitionValueUsedHere) { EXPECT_NEAR(kYt, 4.11346e-3, 1e-8); }

TEST(FiniteWidthWheel, ConfigurationsOfFigure321) {
  // 1: [-2, 2] mm, inside the band and over the centre line.
  SliceSelection s = select_governing_slice(kJoint, cylinder(0.0, 0.004));
  EXPECT_EQ(s.configuration, 1);
  EXPECT_NEAR(s.line_contact_length_m, 0.004, 1e-15);
  // 2: [0.1, 4.1] mm, inside the band, off the centre line.
  s = select_governing_slice(kJoint, cylinder(0.0021, 0.004));
  EXPECT_EQ(s.configuration, 2);
  EXPECT_NEAR(s.line_contact_length_m, 0.004, 1e-15);
  // 3: centred on y_t, half the width in the band: the thesis's "only half".
  s = select_governing_slice(kJoint, cylinder(kYt, 0.004));
  EXPECT_EQ(s.configuration, 3);
  EXPECT_NEAR(s.line_contact_length_m, 0.002, 1e-15);
  EXPECT_TRUE(s.scenario_one);
  // 4: inner edge exactly at y_t: a single disc in scenario 1, point contact.
  s = select_governing_slice(kJoint, cylinder(kYt + 0.002, 0.004));
  EXPECT_EQ(s.configuration, 4);
  EXPECT_TRUE(s.scenario_one);
  EXPECT_NEAR(s.line_contact_length_m, 0.0, 1e-15);
  // 5: wholly beyond y_t: scenario 2, the inner edge governs.
  s = select_governing_slice(kJoint, cylinder(0.010, 0.004));
  EXPECT_EQ(s.configuration, 5);
  EXPECT_FALSE(s.scenario_one);
  EXPECT_NEAR(s.governing_y_m, 0.008, 1e-15);
}

TEST(FiniteWidthWheel, ScenarioOneConfigurationsHaveTheVJump) {
  // Configurations 1-4 all have the plain-V jump 2 M v tan(beta/2) = 1125.0844 N s.
  for (double y : {0.0, 0.0021, kYt, kYt + 0.002}) {
    const ImpactPrediction p = predict_impact(kJoint, cylinder(y, 0.004));
    EXPECT_EQ(p.scenario, ImpactScenario::one) << "y " << y;
    EXPECT_NEAR(p.impulse.exact_Ns, 75000 * std::tan(0.015), 1e-9) << "y " << y;
  }
}

TEST(FiniteWidthWheel, ScenarioTwoIsTheInnerEdgeDisc) {
  WheelParams disc = cylinder(0.008, 0.0);
  const ImpactPrediction edge = predict_impact(kJoint, disc);
  const ImpactPrediction wide = predict_impact(kJoint, cylinder(0.010, 0.004));
  EXPECT_NEAR(wide.impulse.exact_Ns, edge.impulse.exact_Ns, 1e-12 * edge.impulse.exact_Ns);
  // Mirror side: the slice nearest the centre line is the outer-y edge (-8 mm).
  const ImpactPrediction mirrored = predict_impact(kJoint, cylinder(-0.010, 0.004));
  EXPECT_NEAR(mirrored.governing_y_m, -0.008, 1e-15);
  EXPECT_TRUE(mirrored.on_landing);
  EXPECT_NEAR(mirrored.impulse.exact_Ns, edge.impulse.exact_Ns, 1e-9 * edge.impulse.exact_Ns);
}

TEST(FiniteWidthWheel, ReducesToTheDiscAsWidthVanishes) {
  const double disc = predict_impact(kJoint, cylinder(0.015, 0.0)).impulse.exact_Ns;
  double previous_gap = INFINITY;
  for (double width : {4e-3, 1e-3, 1e-4, 1e-6}) {
    const double gap = disc - predict_impact(kJoint, cylinder(0.015, width)).impulse.exact_Ns;
    EXPECT_GT(gap, 0.0) << "the inner edge is nearer y_t, so its jump is smaller";
    EXPECT_LT(gap, previous_gap);
    previous_gap = gap;
  }
  EXPECT_LT(previous_gap / disc, 1e-4);
}

TEST(FiniteWidthWheel, OnlyThePartOnTheRailHeadCounts) {
  // [14, 24] mm clipped to the head [.., 20]: the inner edge 14 mm still governs.
  EXPECT_NEAR(select_governing_slice(kJoint, cylinder(0.019, 0.010)).governing_y_m, 0.014, 1e-15);
  // A wide wheel over the whole head at theta 30: line contact 2 y_t.
  const SliceSelection s = select_governing_slice(kJoint, cylinder(0.0, 0.1));
  EXPECT_NEAR(s.line_contact_length_m, 2 * kYt, 1e-15);
  EXPECT_EQ(s.configuration, 3);
}

TEST(FiniteWidthWheel, SquareJointIsAlwaysFullWidthLineContact) {
  JointParams square = kJoint;
  square.theta_rad = std::numbers::pi / 2;
  const SliceSelection s = select_governing_slice(square, cylinder(0.015, 0.01));
  EXPECT_TRUE(s.scenario_one);
  // [10, 20] mm, all of it on the head and all of it in the (unbounded) band.
  EXPECT_NEAR(s.line_contact_length_m, 0.010, 1e-15);
  EXPECT_EQ(s.configuration, 2);
}

}  // namespace
}  // namespace railjoint
