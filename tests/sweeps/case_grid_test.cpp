// The cases of a sweep file: the product of its axes in the file's order,
// ranges with exact ends, log ranges with a constant ratio, and sampled
// points (random, Latin hypercube) that are reproducible from their seed.

#include "scenes/sweeps/case_grid.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <set>

#include <gtest/gtest.h>

#include "scenes/sweeps/sample_design.h"
#include "scenes/sweeps/sweep_file.h"

namespace railjoint {
namespace {

const std::vector<std::string> kModels = {"analytic", "simulate"};

// A sweep file from text; the base scene's text is given, so no file is read.
SweepFile sweep(const std::string& text) {
  return parse_sweep_file("base = \"default.toml\"\nrun = [\"analytic\"]\n" + text, "test.toml", "", kModels);
}

double number(const SceneValue& value) {
  if (const long long* i = std::get_if<long long>(&value)) return static_cast<double>(*i);
  return std::get<double>(value);
}

std::vector<std::vector<double>> all_cases(const CaseGrid& grid) {
  std::vector<std::vector<double>> cases;
  std::vector<SceneOverride> overrides;
  for (std::uint64_t i = 0; i < grid.size(); ++i) {
    grid.overrides(i, overrides);
    std::vector<double> values;
    for (const SceneOverride& o : overrides) values.push_back(number(o.value));
    cases.push_back(values);
  }
  return cases;
}

TEST(CaseGrid, ProductOfTheAxesInFileOrderLastFastest) {
  // Keys written in an order that is not alphabetical: toml++ sorts a
  // table's keys, the grid must keep the file's order.
  const SweepFile s = sweep("[axes]\n\"wheel.y\" = [0.0, 0.01]\n\"joint.theta_deg\" = [30, 45, 60]\n"
                            "\"joint.beta\" = { from = 0.01, to = 0.03, count = 2 }\n");
  const CaseGrid grid(s);
  ASSERT_EQ(grid.size(), 12u);  // 2 x 3 x 2
  EXPECT_EQ(grid.keys(), (std::vector<std::string>{"wheel.y", "joint.theta_deg", "joint.beta"}));
  const auto cases = all_cases(grid);
  // Nested loops over the axes, the first outermost: the reference the grid must equal.
  std::vector<std::vector<double>> expected;
  for (double y : {0.0, 0.01}) {
    for (double theta : {30.0, 45.0, 60.0}) {
      for (double beta : {0.01, 0.03}) expected.push_back({y, theta, beta});
    }
  }
  EXPECT_EQ(cases, expected);
  std::vector<SceneOverride> overrides;
  grid.overrides(3, overrides);
  EXPECT_EQ(overrides[1].section, "joint");
  EXPECT_EQ(overrides[1].key, "theta_deg");
  EXPECT_TRUE(std::holds_alternative<long long>(overrides[1].value)) << "integers stay integers, as --set reads them";
}

TEST(CaseGrid, EvenRangeHasExactEndsAndEqualSteps) {
  const CaseGrid grid(sweep("[axes]\n\"wheel.y\" = { from = -0.017, to = 0.017, count = 40 }\n"));
  const auto cases = all_cases(grid);
  ASSERT_EQ(cases.size(), 40u);
  EXPECT_EQ(cases.front()[0], -0.017);
  EXPECT_EQ(cases.back()[0], 0.017);
  const double step = 0.034 / 39.0;
  for (std::size_t i = 1; i < cases.size(); ++i) EXPECT_NEAR(cases[i][0] - cases[i - 1][0], step, 1e-15) << i;
}

TEST(CaseGrid, LogRangeHasAConstantRatio) {
  const CaseGrid grid(sweep("[axes]\n\"joint.beta\" = { from = 0.001, to = 0.1, count = 5, scale = \"log\" }\n"));
  const auto cases = all_cases(grid);
  // 0.001 .. 0.1 in 5 values: a factor 10^(2/4) = sqrt(10) per step.
  const std::vector<double> expected = {0.001, 0.001 * std::sqrt(10.0), 0.01, 0.01 * std::sqrt(10.0), 0.1};
  ASSERT_EQ(cases.size(), expected.size());
  for (std::size_t i = 0; i < cases.size(); ++i) EXPECT_NEAR(cases[i][0] / expected[i], 1.0, 1e-14) << i;
  EXPECT_EQ(cases.front()[0], 0.001);
  EXPECT_EQ(cases.back()[0], 0.1);
}

TEST(CaseGrid, SampledPointsTimesTheGridAxes) {
  const SweepFile s = sweep("[axes]\n\"joint.theta_deg\" = [30.0, 60.0]\n\"wheel.y\" = { from = 0.0, to = 0.019 }\n"
                            "\"joint.beta\" = { from = 0.005, to = 0.05, scale = \"log\" }\n"
                            "[sample]\ncount = 50\nseed = 3\n");
  const CaseGrid grid(s);
  ASSERT_EQ(grid.size(), 100u);
  const auto cases = all_cases(grid);
  for (std::size_t i = 0; i < cases.size(); ++i) {
    // The sampled point is the innermost factor: the same 50 points under each theta.
    EXPECT_EQ(cases[i][0], i < 50 ? 30.0 : 60.0);
    EXPECT_EQ(cases[i][1], cases[i % 50][1]);
    EXPECT_GE(cases[i][1], 0.0);
    EXPECT_LE(cases[i][1], 0.019);
    EXPECT_GE(cases[i][2], 0.005);
    EXPECT_LE(cases[i][2], 0.05);
  }
}

// Latin hypercube: in every coordinate, each of the n strata holds exactly one of the n points.
TEST(SampleDesign, LatinHypercubeFillsEveryStratumOnce) {
  for (const std::uint64_t n : {1u, 7u, 100u, 1000u}) {
    const std::size_t dims = 4;
    const std::vector<double> points = unit_sample(n, dims, 42, SampleMethod::latin_hypercube);
    for (std::size_t d = 0; d < dims; ++d) {
      std::set<std::uint64_t> strata;
      for (std::uint64_t i = 0; i < n; ++i) {
        const double x = points[i * dims + d];
        ASSERT_GE(x, 0.0);
        ASSERT_LT(x, 1.0);
        strata.insert(static_cast<std::uint64_t>(x * static_cast<double>(n)));
      }
      EXPECT_EQ(strata.size(), n) << "n " << n << " dimension " << d;
    }
  }
}

// A log range is stratified in log space: each decade of 0.001 .. 1 gets a third of the points.
TEST(CaseGrid, SampledLogRangeStratifiedInLogSpace) {
  const CaseGrid grid(sweep("[axes]\n\"joint.beta\" = { from = 0.001, to = 1.0, scale = \"log\" }\n[sample]\ncount = 300\n"));
  int per_decade[3] = {0, 0, 0};
  for (const auto& c : all_cases(grid)) ++per_decade[std::min(2, static_cast<int>(std::floor(std::log10(c[0]) + 3.0)))];
  EXPECT_EQ(per_decade[0], 100);
  EXPECT_EQ(per_decade[1], 100);
  EXPECT_EQ(per_decade[2], 100);
}

TEST(SampleDesign, SameSeedSamePointsOtherSeedOthers) {
  for (const SampleMethod method : {SampleMethod::random, SampleMethod::latin_hypercube}) {
    const auto a = unit_sample(200, 3, 7, method);
    const auto b = unit_sample(200, 3, 7, method);
    const auto c = unit_sample(200, 3, 8, method);
    EXPECT_EQ(a, b);
    EXPECT_NE(a, c);
  }
  // The generator's sequence is fixed by the C++ standard: the 10000th output
  // of a default-seeded std::mt19937_64 is 9981545732273789042 ([rand.predef]).
  std::mt19937_64 engine;
  engine.discard(9999);
  EXPECT_EQ(engine(), 9981545732273789042ull);
}

TEST(SampleDesign, RandomPointsCoverTheCubeEvenly) {
  // 10000 uniform points: each half of each axis holds 5000 +- 3 sigma (sigma = 50).
  const auto points = unit_sample(10000, 2, 1, SampleMethod::random);
  for (std::size_t d = 0; d < 2; ++d) {
    int low = 0;
    for (std::size_t i = 0; i < 10000; ++i) low += points[i * 2 + d] < 0.5;
    EXPECT_NEAR(low, 5000, 150) << d;
  }
}

}  // namespace
}  // namespace railjoint
