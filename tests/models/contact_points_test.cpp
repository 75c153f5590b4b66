// Top view of the contact points (figure 4.8).

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "models/contact_points.h"
#include "models/inclined_joint.h"

namespace railjoint {
namespace {

TEST(ContactPoints, SquareJointHasFixedContacts) {
  JointParams joint;
  joint.theta_rad = std::numbers::pi / 2;
  const double x_contact = 0.475 * std::sin(0.015);
  for (const TopViewContact& row : top_view_contacts(joint, WheelParams{}, 21)) {
    EXPECT_EQ(row.scenario, ImpactScenario::one);
    EXPECT_NEAR(row.wheel_x_m, 0.0, 1e-12);
    EXPECT_NEAR(row.A_x_m, x_contact, 1e-12);
    EXPECT_NEAR(row.B_x_m, -x_contact, 1e-12);
  }
}

TEST(ContactPoints, ScenarioTwoPutsAOnTheCutAndMirrorsAcrossTheCentreLine) {
  const JointParams joint;  // 30 deg
  const auto rows = top_view_contacts(joint, WheelParams{}, 41);
  const double y_t = transition_y_m(joint, 0.475);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const TopViewContact& row = rows[i];
    const TopViewContact& mirror = rows[rows.size() - 1 - i];
    EXPECT_NEAR(mirror.y_m, -row.y_m, 1e-15);
    EXPECT_NEAR(mirror.wheel_x_m, -row.wheel_x_m, 1e-12);
    if (std::abs(row.y_m) > y_t) {
      // The step-down side is the mirror image: A is the corner the wheel leaves.
      EXPECT_NEAR(mirror.A_x_m, -row.A_x_m, 1e-12);
      EXPECT_NEAR(mirror.B_x_m, -row.B_x_m, 1e-12);
      EXPECT_EQ(mirror.on_landing, row.y_m > 0);
      EXPECT_EQ(row.scenario, ImpactScenario::two);
      EXPECT_NEAR(row.A_x_m, row.cut_x_m, 1e-12) << "A is the corner of the cut";
      EXPECT_GT(std::abs(row.A_x_m - row.wheel_x_m), 0.475 * std::sin(0.015)) << "x_A grows beyond scenario 1";
    } else {
      // The plain V: A ahead on the outgoing rail, B behind, on both sides.
      EXPECT_EQ(row.scenario, ImpactScenario::one);
      EXPECT_NEAR(row.A_x_m, 0.475 * std::sin(0.015), 1e-12);
      EXPECT_NEAR(row.B_x_m, -0.475 * std::sin(0.015), 1e-12);
    }
  }
}

}  // namespace
}  // namespace railjoint
