// A dip given by its depth (models/dip_profile.h): the conversion to the
// angle at the joint against a hand derivation, and the depth read back off
// the rail top itself.

#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "models/dip_profile.h"

namespace railjoint {
namespace {


// By hand. A cosine dip: each rail end at s from the joint is
// (2 t D / pi) sin(pi s / (2 D)) up to D and level beyond, so a straight edge
// on the level rails either side sees the joint d = 2 t D / pi below it, and
// the dip L = 2 D long. With t = tan(beta/2): beta = 2 atan(pi d / (2 D)).
// beta 0.03, D 0.3 m: t = tan(0.015) = 0.0150011251 (tan x = x + x^3/3 +
// 2x^5/15: 0.015 + 1.125e-6 + 1.0e-10), d = 2 x 0.0150011251 x 0.3 / pi =
// 2.865004 mm. Quadratic (t s - t s^2 / (2 D), level t D / 2): d = 2.250169 mm,
// beta = 2 atan(2 d / D). And d = 2 mm, D 0.3 m: cosine beta = 2 atan(pi /
// 300) = 2 (0.0104720 - 3.83e-7) = 0.0209432 rad; quadratic 2 atan(1/75) =
// 2 (0.0133333 - 7.90e-7) = 0.0266651 rad.
TEST(DipDepth, ConversionAgreesWithTheHandDerivation) {
  EXPECT_NEAR(dip_depth_m(DipShape::cosine, 0.03, 0.3), 2.865004e-3, 1e-9);
  EXPECT_NEAR(dip_depth_m(DipShape::quadratic, 0.03, 0.3), 2.250169e-3, 1e-9);
  EXPECT_EQ(dip_depth_m(DipShape::linear, 0.03, 0.3), 0.0);  // no level, no depth
  EXPECT_NEAR(dip_angle_from_depth_rad(DipShape::cosine, 2e-3, 0.3), 0.0209432, 1e-7);
  EXPECT_NEAR(dip_angle_from_depth_rad(DipShape::quadratic, 2e-3, 0.3), 0.0266651, 1e-7);
  // Each is the other's inverse, to round-off.
  for (const DipShape shape : {DipShape::cosine, DipShape::quadratic}) {
    for (const double beta : {1e-3, 0.03, 0.5}) {
      EXPECT_NEAR(dip_angle_from_depth_rad(shape, dip_depth_m(shape, beta, 0.25), 0.25), beta, 1e-15);
    }
  }
}

// The depth is what the rail top itself drops: the height at the joint
// against the level beyond D (dip_height_m, the curve the model and the
// meshes read), on both rail ends.
TEST(DipDepth, IsTheRailTopsDropFromTheLevelToTheJoint) {
  for (const DipShape shape : {DipShape::cosine, DipShape::quadratic}) {
    JointParams joint;
    joint.dip_shape = shape;
    joint.dip_length_m = 0.3;
    joint.beta_rad = dip_angle_from_depth_rad(shape, 2e-3, joint.dip_length_m);
    for (int rail : {0, 1}) {
      const double level_x_m = (rail == 0 ? -1.0 : 1.0) * 0.5;  // beyond D on that side
      const double drop_m = dip_height_m(joint, rail, level_x_m) - dip_height_m(joint, rail, 0.0);
      std::printf("%s rail %d: drop %.9f mm\n", to_string(shape), rail, drop_m * 1e3);
      EXPECT_NEAR(drop_m, 2e-3, 1e-15);
    }
  }
}

}  // namespace
}  // namespace railjoint
