// The simulated jump on seeded random crossings against the exact reference
// (exact_jump_reference.h): a fast subset here, 300 cases under the ctest
// label "study" (random_scene_accuracy_study.cpp). Never tuned to these seeds.

#include <cmath>

#include <gtest/gtest.h>

#include "tests/sim/random_scene_accuracy.h"

namespace railjoint::testing_reference {

void expect_vouched_runs_accurate(const std::vector<AccuracyRow>& rows) {
  print_accuracy_rows(rows);
  print_accuracy_table(rows);
  for (const AccuracyRow& row : rows) {
    // The bound for every realistic scene. A run that cannot vouch
    // for its number says so (verdict "suspect") and is not held to it.
    if (!row.refused && row.vouched) {
      EXPECT_LE(std::abs(row.relative_error), 1e-3) << row.crossing.name;
    }
    // A suspect run must carry its reason.
    if (!row.refused && !row.vouched) {
      EXPECT_FALSE(row.verdict_reason.empty()) << row.crossing.name;
    }
  }
}

namespace {

TEST(RandomSceneAccuracy, FastSubset) {
  std::vector<AccuracyRow> rows;
  for (const RandomCrossing& c : random_crossings(60, 20261123)) rows.push_back(run_accuracy_case(c, SimSettings{}));
  expect_vouched_runs_accurate(rows);
}

}  // namespace
}  // namespace railjoint::testing_reference
