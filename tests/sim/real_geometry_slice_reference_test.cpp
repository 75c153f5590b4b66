// Force runs on real geometry against the independent slice reference
// (real_geometry_slice_comparison.h): the contact force at every recorded
// step within 1 % of P1. Seed 1 was run while the reference was written,
// seed 2 first when the test was; both first showed the two defects of the
// reference's own first draft (A and B are half the curvature sums; G steps
// between a face and an edge within a table cell), fixed in the reference.
// Three scenes a seed here (the table costs ~1.5 s of CPU a scene); six a
// seed in RandomSceneStudy.RealGeometrySliceReference. Measured on those six:
// seed 1 median 1.1e-4, max 1.0e-3 of P1; seed 2 median 5.1e-4, max 1.5e-3.

#include <gtest/gtest.h>

#include "tests/sim/real_geometry_slice_comparison.h"

namespace railjoint::testing_reference {
namespace {

TEST(RealGeometrySliceReference, RandomLumpedCrossingsAgree) { random_slice_scenes(1, 3); }
TEST(RealGeometrySliceReference, RandomLumpedCrossingsOfASecondSeedAgree) { random_slice_scenes(2, 3); }

}  // namespace
}  // namespace railjoint::testing_reference
