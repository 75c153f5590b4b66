// The flat approach before the dip (RailJointMeshOptions::flat_approach_m):
// the incoming rail runs level at the height of the dip's start for the
// given length, one closed solid with a convex kink at x = -L/2.

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "geometry/rail_joint_mesh.h"
#include "support/input_error.h"
#include "tests/geometry/mesh_checks.h"

namespace railjoint {
namespace {

// Thesis joint: theta 30 deg, beta 0.03 rad, b_t 20 mm, L 1 m, depth 50 mm.
const JointParams kJoint{};

TEST(FlatApproach, ZeroLengthIsTheKinematicModelsRail) {
  const RailJointMesh plain = build_rail_joint_mesh(kJoint);
  const RailJointMesh zero = build_rail_joint_mesh(kJoint, RailJointMeshOptions{});
  for (const auto& [a, b] : {std::pair{&plain.incoming, &zero.incoming}, std::pair{&plain.outgoing, &zero.outgoing}}) {
    ASSERT_EQ(a->vertices_m.size(), b->vertices_m.size());
    ASSERT_EQ(a->triangles.size(), b->triangles.size());
    for (std::size_t i = 0; i < a->vertices_m.size(); ++i) EXPECT_EQ(a->vertices_m[i], b->vertices_m[i]);
    for (std::size_t i = 0; i < a->triangles.size(); ++i) EXPECT_EQ(a->triangles[i], b->triangles[i]);
  }
}

TEST(FlatApproach, LevelRailBeforeTheKinkInOneClosedSolid) {
  RailJointMeshOptions options;
  options.flat_approach_m = 0.5;
  const RailJointMesh mesh = build_rail_joint_mesh(kJoint, options);
  const TriangleMesh& in = mesh.incoming;
  std::cout << in.triangles.size() << " triangles, " << in.vertices_m.size() << " vertices\n";
  EXPECT_EQ(test::manifold_defects(in), "");
  // Two prisms along x (flat, slope) sharing the kink section: 3 sections of
  // 4 corners; per piece top 2 + bottom 2 + sides 4 triangles, plus end 2 and cut 2.
  EXPECT_EQ(in.vertices_m.size(), 12u);
  EXPECT_EQ(in.triangles.size(), 20u);
  // The dip's start is at x = -L/2 = -0.5 m, z = tan(beta/2) L/2 = tan(0.015) * 0.5 = 7.5005626e-3 m.
  const double h = std::tan(0.015) * 0.5;
  EXPECT_NEAR(flat_approach_height_m(kJoint), h, 1e-15);
  int flat_top = 0, kink_top = 0;
  for (const Eigen::Vector3d& p : in.vertices_m) {
    if (p.z() < 0.0) continue;  // bottom layer at -depth
    if (std::abs(p.x() + 1.0) < 1e-12) {
      ++flat_top;
      EXPECT_NEAR(p.z(), h, 1e-15);
    }
    if (std::abs(p.x() + 0.5) < 1e-12) {
      ++kink_top;
      EXPECT_NEAR(p.z(), h, 1e-15);
    }
  }
  EXPECT_EQ(flat_top, 2);  // start of the flat, y = -+b_t
  EXPECT_EQ(kink_top, 2);
  // The flat adds a box 0.5 m long, 2 b_t = 0.04 m wide, from -depth to h:
  // 0.5 * 0.04 * (0.05 + h) m^3.
  const double added = signed_volume_m3(in) - signed_volume_m3(build_rail_joint_mesh(kJoint).incoming);
  EXPECT_NEAR(added, 0.5 * 0.04 * (0.05 + h), 1e-15);
  // The outgoing rail is untouched.
  const TriangleMesh plain_out = build_rail_joint_mesh(kJoint).outgoing;
  ASSERT_EQ(mesh.outgoing.vertices_m.size(), plain_out.vertices_m.size());
  for (std::size_t i = 0; i < plain_out.vertices_m.size(); ++i) EXPECT_EQ(mesh.outgoing.vertices_m[i], plain_out.vertices_m[i]);
}

TEST(FlatApproach, NegativeLengthIsRejected) {
  RailJointMeshOptions options;
  options.flat_approach_m = -0.1;
  try {
    build_rail_joint_mesh(kJoint, options);
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(error.key(), "sim.flat_approach");
  }
}

}  // namespace
}  // namespace railjoint
