// The shared rail-top formula: cut position (with the gap), heights on both
// rails, NaN where there is no rail, and the step at the cut.

#include "models/rail_top.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>

#include "tests/geometry/joint_cases.h"

namespace railjoint {
namespace {

using test::JointCase;

// A few floating-point operations on values up to 1.5 m (ulp 2.2e-16 m);
// 0 seen. The mistakes looked for are of order tan(beta/2) x ~ 1e-3 m.
constexpr double kTol_m = 2e-15;

class RailTopTest : public testing::TestWithParam<JointCase> {};

TEST_P(RailTopTest, CutFacesAtTheShiftedCutLine) {
  const JointParams& j = GetParam().joint;
  double worst = 0.0;
  for (const double fraction : {-1.0, -0.5, 0.0, 0.3, 1.0}) {
    const double y = fraction * j.half_width_m;
    for (int rail = 0; rail < 2; ++rail) {
      const double deviation = cut_x_m(j, y, rail) - test::expected_cut_x(j, y, rail);
      worst = std::max(worst, std::abs(deviation));
      EXPECT_NEAR(deviation, 0.0, kTol_m) << "y = " << y << " rail " << rail;
    }
  }
  std::cout << "largest cut deviation " << worst << " m\n";
}

// Random points over the whole plan (and a margin around it) against the
// formula: incoming top left of the incoming cut face, outgoing right of the
// outgoing one, NaN in the gap and off the rail head.
TEST_P(RailTopTest, HeightAtSampledPoints) {
  const JointParams& j = GetParam().joint;
  std::mt19937 random(12345);
  std::uniform_real_distribution<double> xs(-0.55 * j.length_m, 0.55 * j.length_m);
  std::uniform_real_distribution<double> ys(-1.2 * j.half_width_m, 1.2 * j.half_width_m);
  int on_incoming = 0, on_outgoing = 0, off_rail = 0;
  double worst = 0.0;
  for (int n = 0; n < 20000; ++n) {
    const double x = xs(random), y = ys(random);
    const double height = rail_top_height_m(j, x, y);
    const bool on_head = std::abs(y) <= j.half_width_m && std::abs(x) <= j.length_m / 2.0;
    if (on_head && x < test::expected_cut_x(j, y, 0)) {
      ++on_incoming;
      worst = std::max(worst, std::abs(height - test::expected_top(j, 0, x)));
      ASSERT_NEAR(height, test::expected_top(j, 0, x), kTol_m) << x << ", " << y;
    } else if (on_head && x > test::expected_cut_x(j, y, 1)) {
      ++on_outgoing;
      worst = std::max(worst, std::abs(height - test::expected_top(j, 1, x)));
      ASSERT_NEAR(height, test::expected_top(j, 1, x), kTol_m) << x << ", " << y;
    } else {
      ++off_rail;
      ASSERT_TRUE(std::isnan(height)) << "no rail at " << x << ", " << y << " but height " << height;
    }
  }
  std::cout << on_incoming << " points on the incoming rail, " << on_outgoing << " on the outgoing, " << off_rail
            << " off the rails; largest deviation " << worst << " m\n";
  EXPECT_GT(on_incoming, 1000);
  EXPECT_GT(on_outgoing, 1000);
}

// Just either side of the cut of a gap-free joint the top jumps by
// 2 tan(beta/2) y cot(theta) (u0 for the step joint).
TEST_P(RailTopTest, StepAcrossTheCut) {
  JointParams j = GetParam().joint;
  j.gap_m = 0.0;
  const double eps = 1e-9;  // [m]; changes the heights by tan(beta/2) eps < 3e-11 m
  for (const double fraction : {-1.0, -0.6, -0.1, 0.0, 0.45, 1.0}) {
    const double y = fraction * j.half_width_m;
    const double cut = test::expected_cut_x(j, y, 0);
    const double step = rail_top_height_m(j, cut + eps, y) - rail_top_height_m(j, cut - eps, y);
    const double expected = test::is_step(j) ? j.step_height_m : 2.0 * test::tan_half_beta(j) * y * test::cot_theta(j);
    EXPECT_NEAR(step, expected, 1e-10) << "y = " << y;
    // On the line itself the incoming rail is the one (documented); evaluated
    // at the function's own cut x, as the formula's may differ by an ulp.
    const double own_cut = cut_x_m(j, y, 0);
    EXPECT_EQ(rail_top_height_m(j, own_cut, y), test::expected_top(j, 0, own_cut));
  }
}

INSTANTIATE_TEST_SUITE_P(Joints, RailTopTest, testing::ValuesIn(test::joint_cases()),
                         [](const auto& joint_case) { return joint_case.param.name; });

// Spot values by hand, thesis joint (theta 30 deg, beta 0.03): at y = 15 mm the
// cut is at 15 mm * cot 30 deg = 25.98 mm; at x = 20 mm (incoming) the top is
// -tan(0.015) * 20 mm = -0.30002 mm, at x = 30 mm (outgoing) +0.45003 mm.
TEST(RailTop, ThesisSpotValues) {
  const JointParams j;
  EXPECT_NEAR(cut_x_m(j, 0.015, 0), 0.0259808, 1e-7);
  EXPECT_NEAR(rail_top_height_m(j, 0.020, 0.015), -0.30002e-3, 1e-8);
  EXPECT_NEAR(rail_top_height_m(j, 0.030, 0.015), 0.45003e-3, 1e-8);
  // Same x = 20 mm at y = -15 mm (cut at -25.98 mm) is on the outgoing rail.
  EXPECT_NEAR(rail_top_height_m(j, 0.020, -0.015), 0.30002e-3, 1e-8);
}

}  // namespace
}  // namespace railjoint
