// Issue 29, item 9: in a flight the side view followed the wheel's lowest
// point and the rails fell out of the frame (a 6.8 mm flight x20 is 135 mm
// drawn, the default view 67 mm high at 16:9). The framing now finds the rail
// top under the wheel and looks between the two, and widens a render whose
// flights do not fit.

#include <cmath>

#include <gtest/gtest.h>

#include "geometry/rail_joint_mesh.h"
#include "models/parameters.h"
#include "renders/side_view_framing.h"

namespace railjoint {
namespace {

// The default joint (theta 30 deg, beta 0.03, b_t 20 mm, L 1 m): the rail
// tops are the planes z = -tan(beta/2) x (incoming, x below the cut) and
// z = +tan(beta/2) x (outgoing); at y = 15 mm the cut is at x = y cot 30 deg.
class SideViewFramingTest : public ::testing::Test {
 protected:
  JointParams joint{};
  RailJointMesh rails = build_rail_joint_mesh(joint);
  VerticalExaggeration exaggeration{20.0, 0.0};
  SideViewFraming framing{{&rails.incoming, &rails.outgoing}, 0.015, 0.475, exaggeration};
  double slope = std::tan(0.5 * joint.beta_rad);
};

TEST_F(SideViewFramingTest, TheRailTopUnderTheWheelIsTheDipsPlanes) {
  EXPECT_NEAR(framing.rail_top_m(-0.3), 0.3 * slope, 1e-12);
  EXPECT_NEAR(framing.rail_top_m(0.2), 0.2 * slope, 1e-12);
  EXPECT_TRUE(std::isnan(framing.rail_top_m(0.6))) << "beyond the rail ends at +-L/2";
}

TEST_F(SideViewFramingTest, InTheAirTheViewLooksBetweenWheelAndRail) {
  // Resting on the slope: the centre R / cos gamma above the top under it,
  // clearance 0, and the view on the lowest point, R below the centre, as before.
  const Eigen::Vector3d resting(0.2, 0.015, 0.475 / std::cos(std::atan(slope)) + 0.2 * slope);
  EXPECT_NEAR(framing.clearance_m(resting), 0.0, 1e-12);
  EXPECT_NEAR(framing.focus(resting).z(), 20.0 * (resting.z() - 0.475), 1e-12);
  // 5 mm up: the middle of the drawn gap between the lowest point and the top under it.
  const Eigen::Vector3d flying = resting + Eigen::Vector3d(0.0, 0.0, 0.005);
  EXPECT_NEAR(framing.clearance_m(flying), 0.005 * std::cos(std::atan(slope)), 1e-12);
  EXPECT_NEAR(framing.focus(flying).z(), 10.0 * (flying.z() - 0.475 + 0.2 * slope), 1e-12);
}

TEST_F(SideViewFramingTest, AFlightWidensTheViewForTheWholeRender) {
  Trajectory trajectory;
  for (int i = 0; i <= 10; ++i) {
    WheelSample s;
    s.time_s = 1e-3 * i;
    const double x = 0.05 + 0.02 * i;
    const double clearance = i == 5 ? 0.005 : 0.0;  // one sample 5 mm up, the others resting
    s.centre_m = Eigen::Vector3d(x, 0.015, 0.475 / std::cos(std::atan(slope)) + x * slope + clearance);
    trajectory.samples.push_back(s);
  }
  FrameWindow window{0.0, 0.01, 1000.0, 11};
  // Drawn gap 20 x (5 mm + R (1 / cos gamma - 1)) in at most 0.6 of the height, at 16:9.
  const double gap_drawn = 20.0 * (0.005 + 0.475 * (1.0 / std::cos(std::atan(slope)) - 1.0));
  EXPECT_NEAR(framing.width_for_flights(trajectory, window, 0.12, 16.0 / 9.0), gap_drawn / 0.6 * 16.0 / 9.0, 1e-9);
  // Outside the window the flight does not count; a wide view stays.
  FrameWindow before{0.0, 0.004, 1000.0, 5};
  EXPECT_DOUBLE_EQ(framing.width_for_flights(trajectory, before, 0.12, 16.0 / 9.0), 0.12);
  EXPECT_DOUBLE_EQ(framing.width_for_flights(trajectory, window, 1.0, 16.0 / 9.0), 1.0);
}

}  // namespace
}  // namespace railjoint
