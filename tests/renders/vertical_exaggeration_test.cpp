// Vertical exaggeration: heights stretched about z_ref, the rigid wheel
// carried R above the stretched profile.

#include <iostream>

#include <gtest/gtest.h>

#include "renders/vertical_exaggeration.h"

namespace railjoint {
namespace {

TEST(VerticalExaggeration, StretchesHeightsAboutTheReference) {
  const VerticalExaggeration e{20.0, 0.001, 0.475};
  // z = 0.0015: 0.5 mm above the reference -> 20 * 0.5 mm = 10 mm above it -> 0.011 m.
  const Eigen::Vector3d drawn = e.point({0.3, -0.02, 0.0015});
  std::cout << "drawn " << drawn.transpose() << "\n";
  EXPECT_DOUBLE_EQ(drawn.x(), 0.3);
  EXPECT_DOUBLE_EQ(drawn.y(), -0.02);
  EXPECT_NEAR(drawn.z(), 0.011, 1e-15);
  // The reference height itself does not move.
  EXPECT_DOUBLE_EQ(e.point({0.0, 0.0, 0.001}).z(), 0.001);
}

TEST(VerticalExaggeration, WheelTouchingBelowItsCentreIsDrawnTouching) {
  // A wheel resting on a rail point p has its centre at p + (0, 0, R); the
  // drawn centre must be R above the drawn p, for any k and z_ref.
  for (double k : {1.0, 20.0, 500.0}) {
    const VerticalExaggeration e{k, -0.002, 0.475};
    const Eigen::Vector3d rail_point(0.1, 0.015, 0.0037);
    const Eigen::Vector3d centre = rail_point + Eigen::Vector3d(0, 0, 0.475);
    const double gap = e.wheel_centre(centre).z() - e.point(rail_point).z();
    std::cout << "k = " << k << ": drawn centre - drawn contact = " << gap << " m\n";
    EXPECT_NEAR(gap, 0.475, 1e-12);  // a few ulps of the 0.5 m numbers
  }
}

TEST(VerticalExaggeration, LiftOffShowsAsKTimesTheGap) {
  // Centre 1 mm higher than resting: drawn k mm higher.
  const VerticalExaggeration e{20.0, 0.0, 0.475};
  const double resting = e.wheel_centre({0, 0, 0.475}).z();
  const double lifted = e.wheel_centre({0, 0, 0.476}).z();
  EXPECT_NEAR(lifted - resting, 0.020, 1e-12);
}

}  // namespace
}  // namespace railjoint
