// The simulated jump on seeded random crossings against the exact reference
// (exact_jump_reference.h): a fast subset here, 300 cases under the ctest
// label "study" (random_scene_accuracy_study.cpp). Never tuned to these seeds.

#include <gtest/gtest.h>

#include "tests/sim/random_scene_accuracy.h"
#include "tests/sim/real_geometry_accuracy.h"
#include "tests/sim/real_geometry_inertial.h"

namespace railjoint::testing_reference {
namespace {

TEST(RandomSceneAccuracy, FastSubset) {
  std::vector<AccuracyRow> rows;
  for (const RandomCrossing& c : random_crossings(60, 20261123)) rows.push_back(run_accuracy_case(c, SimSettings{}));
  expect_vouched_runs_accurate(rows);
}

TEST(RandomSceneAccuracy, InertialStrikesAndLandingsFastSubset) {
  std::vector<LandingRow> rows;
  for (const RandomCrossing& c : strike_crossings(random_crossings(60, 20261123))) rows.push_back(run_landing_case(c));
  expect_landings_accurate(rows);
}

TEST(RandomSceneAccuracy, RealGeometryFastSubset) {
  std::vector<AccuracyRow> rows;
  for (const RandomCrossing& c : real_geometry_crossings(25, 20261126)) {
    rows.push_back(run_real_geometry_case(c, SimSettings{}));
  }
  for (const RandomCrossing& c : rail_60e1_crossings(10, 20261126)) rows.push_back(run_real_geometry_case(c, SimSettings{}));
  expect_real_geometry_accurate(rows);
}

// Inertial rigid runs on real geometry (real_geometry_inertial.h); seed
// 20261127 was the one looked at while writing them.
TEST(RandomSceneAccuracy, RealGeometryInertialFastSubset) {
  std::vector<RealInertialRow> rows;
  for (const RandomCrossing& c : real_geometry_crossings(15, 20261127)) rows.push_back(run_real_inertial_case(c));
  for (const RandomCrossing& c : rail_60e1_crossings(5, 20261127)) rows.push_back(run_real_inertial_case(c));
  expect_real_inertial_accurate(rows);
}

}  // namespace
}  // namespace railjoint::testing_reference
