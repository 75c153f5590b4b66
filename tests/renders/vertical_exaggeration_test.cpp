// Vertical exaggeration: one affine map for everything drawn, wheel included.

#include <cmath>
#include <iostream>
#include <limits>
#include <numbers>

#include <gtest/gtest.h>

#include "renders/vertical_exaggeration.h"

namespace railjoint {
namespace {

TEST(VerticalExaggeration, StretchesHeightsAboutTheReference) {
  const VerticalExaggeration e{20.0, 0.001};
  // z = 0.0015: 0.5 mm above the reference -> 20 * 0.5 mm = 10 mm above it -> 0.011 m.
  const Eigen::Vector3d drawn = e.point({0.3, -0.02, 0.0015});
  std::cout << "drawn " << drawn.transpose() << "\n";
  EXPECT_DOUBLE_EQ(drawn.x(), 0.3);
  EXPECT_DOUBLE_EQ(drawn.y(), -0.02);
  EXPECT_NEAR(drawn.z(), 0.011, 1e-15);
  // The reference height itself does not move.
  EXPECT_DOUBLE_EQ(e.point({0.0, 0.0, 0.001}).z(), 0.001);
}

TEST(VerticalExaggeration, MatrixIsTheSameMapAsPoint) {
  const VerticalExaggeration e{37.0, -0.0021};
  for (const Eigen::Vector3d& p : {Eigen::Vector3d(0.1, 0.015, 0.47), Eigen::Vector3d(-0.3, -0.02, -0.05)}) {
    const Eigen::Vector3d by_matrix = (e.matrix() * p.homogeneous()).hnormalized();
    EXPECT_LT((by_matrix - e.point(p)).norm(), 1e-14) << p.transpose();
  }
}

TEST(VerticalExaggeration, LiftOffShowsAsKTimesTheGap) {
  // The wheel's lowest point 1 mm higher: drawn k mm higher.
  const VerticalExaggeration e{20.0, 0.0};
  const double resting = e.lowest_wheel_point({0, 0, 0.475}, 0.475).z();
  const double lifted = e.lowest_wheel_point({0, 0, 0.476}, 0.475).z();
  EXPECT_NEAR(resting, 0.0, 1e-15);
  EXPECT_NEAR(lifted - resting, 0.020, 1e-12);
}

// A circle of radius R resting on the line z = -t x (a wheel on the incoming
// slope of the dip, t = tan(beta/2)) touches it at the foot of the normal
// through its centre, p = c - R (t, 0, 1) / sqrt(1 + t^2), and lies above it
// everywhere else. Mapped by the same affine map, the ellipse must lie above
// the mapped line everywhere and touch it at the mapped p. The old drawing,
// a rigid circle whose centre rides R above the exaggerated profile
// (z' = R + k (z_c - R)), cuts into the k-times steeper line.
TEST(VerticalExaggeration, CircleTangentToALineStaysTangentAtTheMappedPoint) {
  const double R = 0.475, t = std::tan(0.015), k = 20.0;
  const VerticalExaggeration e{k, 0.0};
  const double xc = -0.2;
  const Eigen::Vector3d c(xc, 0.015, -t * xc + R * std::sqrt(1.0 + t * t));
  const Eigen::Vector3d p = c - R * Eigen::Vector3d(t, 0.0, 1.0) / std::sqrt(1.0 + t * t);
  EXPECT_NEAR(p.z(), -t * p.x(), 1e-15);  // p lies on the line

  const Eigen::Vector3d drawn_p = e.point(p);
  const Eigen::Vector3d old_centre(c.x(), c.y(), R + k * (c.z() - R));
  double min_gap = std::numeric_limits<double>::infinity(), x_at_min = 0.0, rigid_min_gap = min_gap;
  for (int i = 0; i < 200000; ++i) {
    const double phi = 2.0 * std::numbers::pi * i / 200000;
    // Affinely mapped circle point, and the old rigid circle's point.
    const Eigen::Vector3d q = e.point(c + R * Eigen::Vector3d(std::cos(phi), 0.0, std::sin(phi)));
    const Eigen::Vector3d rigid = old_centre + R * Eigen::Vector3d(std::cos(phi), 0.0, std::sin(phi));
    const double gap = q.z() - k * (-t * q.x());  // height above the drawn line z' = -k t x
    if (gap < min_gap) {
      min_gap = gap;
      x_at_min = q.x();
    }
    rigid_min_gap = std::min(rigid_min_gap, rigid.z() - k * (-t * rigid.x()));
  }
  std::cout << "ellipse: smallest height above the drawn line " << min_gap << " m at x = " << x_at_min
            << " m (mapped contact at x = " << drawn_p.x() << " m); rigid circle: " << rigid_min_gap << " m\n";
  // Sampling every 2 pi / 2e5 rad puts a sample within R pi / 2e5 = 7.5 um of
  // p along the rim; the gap there is k * (7.5 um)^2 / (2 R) ~ 1e-9 m.
  EXPECT_GT(min_gap, -1e-12);
  EXPECT_LT(min_gap, 1e-8);
  EXPECT_NEAR(x_at_min, drawn_p.x(), 1e-5);
  // The old rigid circle reaches R (1 - sqrt(1 + (k t)^2)) + k R (sqrt(1 + t^2) - 1)
  // = -20.9 mm + 1.1 mm = -19.8 mm, i.e. below the steeper drawn line.
  EXPECT_NEAR(rigid_min_gap, R * (1.0 - std::sqrt(1.0 + k * k * t * t)) + k * R * (std::sqrt(1.0 + t * t) - 1.0),
              1e-6);
  EXPECT_LT(rigid_min_gap, -0.015);
}

}  // namespace
}  // namespace railjoint
