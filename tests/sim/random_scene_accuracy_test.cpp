// The simulated jump on seeded random crossings against the exact reference
// (exact_jump_reference.h): a fast subset here, 300 cases under the ctest
// label "study" (random_scene_accuracy_study.cpp). Never tuned to these seeds.

#include <gtest/gtest.h>

#include "tests/sim/random_scene_accuracy.h"
#include "tests/sim/real_geometry_accuracy.h"
#include "tests/sim/real_geometry_inertial.h"

namespace railjoint::testing_reference {
namespace {

TEST(RandomSceneAccuracy, FastSubset) { expect_random_crossings_accurate(60, 20261123); }

TEST(RandomSceneAccuracy, LowSpeedFastSubset) { expect_low_speed_crossings_accurate(60, 20261123); }

TEST(RandomSceneAccuracy, InertialStrikesAndLandingsFastSubset) { expect_random_landings_accurate(60, 20261123); }

TEST(RandomSceneAccuracy, RealGeometryFastSubset) { expect_real_geometry_crossings_accurate(25, 10, 20261126); }

// Inertial rigid runs on real geometry (real_geometry_inertial.h); seed
// 20261127 was the one looked at while writing them.
TEST(RandomSceneAccuracy, RealGeometryInertialFastSubset) { expect_real_inertial_crossings_accurate(15, 5, 20261127); }

// Seed 7373's crown#45 (a 23 mm wheel on a 694 mm crown, theta 60 deg,
// beta 0.0066, 38.6 m/s): the path bends down at
// 19.7 times what the load can follow just after a 196.85 N s strike, so
// the wheel flies 3.4 mm, at most 0.15 um high, and lands with 5.197 N s
// (the ballistic reference). The run used to vouch for the strike alone:
// the landing, 2x v^2 / R in its one fine step, was below the jump
// detector's acceleration bound, and the hold put the wheel back across
// the flight's first 1.6 nm (9 um early, 0.5 % soft). Its landing must now
// be found within the study's 1e-3, or the run must say it cannot.
TEST(RandomSceneAccuracy, ALowFlightAfterAStrikeLandsOrIsSuspect) {
  std::vector<RealInertialRow> rows;
  for (const RandomCrossing& c : real_geometry_crossings(100, 7373)) {
    if (c.name == "crown#45") rows.push_back(run_real_inertial_case(c));
  }
  ASSERT_EQ(rows.size(), 1u);
  const RealInertialRow& row = rows.front();
  ASSERT_TRUE(row.reference.flies_after);
  EXPECT_NEAR(row.reference.landing_Ns, 5.197, 1e-3);
  expect_real_inertial_accurate(rows);
}

}  // namespace
}  // namespace railjoint::testing_reference
