// 1000 seeded random crossings against the exact reference, with the table of
// median, 90th percentile and maximum |error| per group (README). Label
// "study": ctest --test-dir build -L study -R RandomSceneStudy -V

#include <gtest/gtest.h>

#include "tests/sim/random_scene_accuracy.h"
#include "tests/sim/real_geometry_accuracy.h"
#include "tests/sim/real_geometry_inertial.h"
#include "tests/sim/real_geometry_slice_comparison.h"

namespace railjoint::testing_reference {
namespace {

TEST(RandomSceneStudy, AThousandCrossings) { expect_random_crossings_accurate(1000, 4242); }

TEST(RandomSceneStudy, InertialStrikesAndLandings) { expect_random_landings_accurate(1000, 4242); }

// The same crossings at 2-10 m/s, where a pivot before a landing is stepped
// by its angle (sim/step_control.h): seed 1 was run while writing that,
// seed 4343 only after it.
TEST(RandomSceneStudy, LowSpeedCrossings) {
  for (const std::uint64_t seed : {1u, 4343u}) {
    std::printf("seed %llu\n", static_cast<unsigned long long>(seed));
    expect_low_speed_crossings_accurate(1000, seed);
  }
}

// Their landings after a pivot in inertial mode where the load holds the
// wheel on the pivot (the rigid inertial run's own step rules and hold).
TEST(RandomSceneStudy, LowSpeedInertialLandings) {
  for (const std::uint64_t seed : {1u, 4343u}) {
    std::printf("seed %llu\n", static_cast<unsigned long long>(seed));
    expect_low_speed_inertial_landings_accurate(1000, seed);
  }
}

// Seed 5151 was first run once the general model and its narrow phase were
// written (the fast subset's 20261126 was used while writing them); its 3
// suspect runs led to the pivot preload and step (sim/crossing_model.cpp,
// sim/step_control.cpp). Seed 9001 was run only after that.
TEST(RandomSceneStudy, RealGeometry) {
  for (const std::uint64_t seed : {5151u, 9001u}) {
    std::printf("seed %llu\n", static_cast<unsigned long long>(seed));
    expect_real_geometry_crossings_accurate(300, 100, seed);
  }
}

// Inertial rigid runs on real geometry (real_geometry_inertial.h): seed 6262
// was first run once the test was written (the fast subset's 20261127 while
// writing it), 7373 after it.
TEST(RandomSceneStudy, RealGeometryInertial) {
  for (const std::uint64_t seed : {6262u, 7373u}) {
    std::printf("seed %llu\n", static_cast<unsigned long long>(seed));
    expect_real_inertial_crossings_accurate(100, 40, seed);
  }
}

// Force runs on real geometry against the slice reference, six scenes a
// seed (the default suite runs the first three of each).
TEST(RandomSceneStudy, RealGeometrySliceReference) {
  random_slice_scenes(1, 6);
  random_slice_scenes(2, 6);
}

// The same on curved dips and end-post gaps (lumped track): seed 3 was
// first run when the test was written, seed 4 after it.
TEST(RandomSceneStudy, RealGeometrySliceReferenceDipsAndGaps) {
  random_slice_scenes(3, 6, true);
  random_slice_scenes(4, 6, true);
}

}  // namespace
}  // namespace railjoint::testing_reference
