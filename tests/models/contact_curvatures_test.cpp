// The curvatures every Hertz ellipse takes (models/contact_curvatures.h),
// against closed forms: a cone of conicity c (r = R - c y) on a head crowned
// with radius R_c, at the crown's top (y = 0, slope 0).

#include <cmath>

#include <gtest/gtest.h>

#include "models/contact_curvatures.h"

namespace railjoint {
namespace {

TEST(ContactCurvatures, AConeOnACrownMatchesTheClosedForms) {
  JointParams joint;
  joint.crown_radius_m = 0.3;
  joint.beta_rad = 0.0;
  WheelParams wheel;
  wheel.radius_m = 0.475;
  wheel.conicity = 0.05;
  wheel.lateral_m = 0.0;  // the rolling circle (r = R) at y = 0
  const ContactCurvatures k = contact_curvatures_at(joint, wheel, 0, -0.05, 0.0);
  // Meusnier: the rolling circle's normal curvature is cos(psi) / r with
  // tan(psi) = r' = -c, so 1 / (R sqrt(1 + c^2)): 0.125 % below 1 / R at 1/20.
  EXPECT_NEAR(k.wheel_along_x_per_m, 1.0 / (0.475 * std::sqrt(1.0 + 0.05 * 0.05)), 1e-9);
  // A cone is straight across (r'' = 0); the crown's top has curvature 1 / R_c;
  // the rail is straight along (no dip). 1e-6 / m: the difference's round-off
  // (slopes of 1e-16 over 2 um).
  EXPECT_NEAR(k.wheel_across_y_per_m, 0.0, 1e-6);
  EXPECT_NEAR(k.rail_across_y_per_m, 1.0 / 0.3, 1e-6);
  EXPECT_NEAR(k.rail_along_x_per_m, 0.0, 1e-6);
}

}  // namespace
}  // namespace railjoint
