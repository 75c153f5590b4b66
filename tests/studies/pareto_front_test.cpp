// The Pareto front of an error-against-cost cloud, on hand-made points whose
// front is read off by eye (written next to each point).

#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include <gtest/gtest.h>

#include "scenes/studies/pareto_front.h"

namespace railjoint {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

const std::vector<ParetoPoint> kCloud = {
    {1e-2, 1.0},   // 0: fastest -> front
    {1e-3, 2.0},   // 1: more accurate than 0 -> front
    {2e-3, 3.0},   // 2: worse and slower than 1 -> dominated (by 1 by 2x in error, 1.5x in cost)
    {kNaN, 0.5},   // 3: no result -> never on the front, though fastest
    {1e-9, 10.0},  // 4: below the resolution 1e-6, counts as 1e-6 -> front (most accurate)
    {1e-12, 20.0}, // 5: also "1e-6" but slower than 4 -> dominated
    {1e-2, 1.05},  // 6: same error as 0, 5 % slower -> dominated, within 10 %
    {0.995e-3, 3.5},  // 7: 0.5 % more accurate than 1 (within the 1 % tie), slower -> dominated by 1
};

TEST(ParetoFront, KeepsTheNonDominatedPointsByIncreasingCost) {
  const std::vector<std::size_t> front = pareto_front(kCloud);
  ASSERT_EQ(front.size(), 3u);
  EXPECT_EQ(front[0], 0u);
  EXPECT_EQ(front[1], 1u);
  EXPECT_EQ(front[2], 4u);
}

TEST(ParetoFront, DominationIsTheLargestGainOfADominatingPoint) {
  for (const std::size_t i : {0u, 1u, 4u}) {
    const Domination d = domination(kCloud, i);
    EXPECT_DOUBLE_EQ(d.factor, 1.0) << i;
    EXPECT_FALSE(d.by.has_value()) << i;
  }
  // Point 1 dominates point 2: 2e-3 / 1e-3 = 2 in error, 3 / 2 = 1.5 in cost -> 2.
  Domination d = domination(kCloud, 2);
  EXPECT_DOUBLE_EQ(d.factor, 2.0);
  EXPECT_EQ(d.by, std::optional<std::size_t>(1));
  EXPECT_TRUE(std::isnan(domination(kCloud, 3).factor));
  // Point 4 is as accurate (both resolve to 1e-6) and twice as fast as point 5.
  d = domination(kCloud, 5);
  EXPECT_DOUBLE_EQ(d.factor, 2.0);
  EXPECT_EQ(d.by, std::optional<std::size_t>(4));
  // Point 0: same error as 6, 1.05 / 1 = 5 % faster -> within 10 % of the front.
  d = domination(kCloud, 6);
  EXPECT_DOUBLE_EQ(d.factor, 1.05);
  EXPECT_EQ(d.by, std::optional<std::size_t>(0));
  // Point 1 is as accurate (within the tie) and 3.5 / 2 = 1.75 times faster than point 7.
  d = domination(kCloud, 7);
  EXPECT_DOUBLE_EQ(d.factor, 1.75);
  EXPECT_EQ(d.by, std::optional<std::size_t>(1));
}

TEST(ParetoFront, EmptyAndAllFailed) {
  EXPECT_TRUE(pareto_front({}).empty());
  EXPECT_TRUE(pareto_front({{kNaN, 1.0}, {1e-3, kNaN}}).empty());
}

}  // namespace
}  // namespace railjoint
