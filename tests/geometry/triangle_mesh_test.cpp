// signed_volume_m3 on solids whose volume is known by hand.

#include "geometry/triangle_mesh.h"

#include <gtest/gtest.h>

#include "tests/geometry/mesh_checks.h"

namespace railjoint {
namespace {

// Corner tetrahedron (0, a e_x, b e_y, c e_z): volume a b c / 6.
TriangleMesh corner_tetrahedron(double a, double b, double c) {
  TriangleMesh mesh;
  mesh.vertices_m = {{0, 0, 0}, {a, 0, 0}, {0, b, 0}, {0, 0, c}};
  // Outward: the base z = 0 seen from below is 0, 2, 1; the sloped face 1, 2, 3.
  mesh.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  mesh.tags.assign(4, FaceTag::top);
  return mesh;
}

TEST(TriangleMesh, SignedVolumeOfACornerTetrahedron) {
  TriangleMesh mesh = corner_tetrahedron(0.3, 0.2, 0.5);
  ASSERT_EQ(test::manifold_defects(mesh), "");
  const double expected = 0.3 * 0.2 * 0.5 / 6.0;
  std::cout << "volume " << signed_volume_m3(mesh) << " m^3, expected " << expected << "\n";
  EXPECT_NEAR(signed_volume_m3(mesh), expected, 1e-16);  // a few round-offs of 1e-2 m^3 terms

  // The divergence-theorem sum does not depend on where the origin is.
  for (Eigen::Vector3d& v : mesh.vertices_m) v += Eigen::Vector3d(1.5, -2.0, 0.7);
  EXPECT_NEAR(signed_volume_m3(mesh), expected, 1e-15);  // terms of order 1 m^3 now cancel

  // Inward winding flips the sign.
  for (Eigen::Vector3i& t : mesh.triangles) std::swap(t[1], t[2]);
  EXPECT_NEAR(signed_volume_m3(mesh), -expected, 1e-15);
}

}  // namespace
}  // namespace railjoint
