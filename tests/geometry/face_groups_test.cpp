// Splitting a tagged solid into one mesh per face: every triangle once, in
// the group its tag names, with the faces where the geometry puts them.

#include "geometry/face_groups.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <map>
#include <numbers>
#include <string>

#include "geometry/rail_joint_mesh.h"
#include "geometry/wheel_mesh.h"

namespace railjoint {
namespace {

Eigen::Vector3d unit_normal(const TriangleMesh& mesh, std::size_t t) {
  const Eigen::Vector3i& f = mesh.triangles[t];
  const Eigen::Vector3d& a = mesh.vertices_m[f[0]];
  return (mesh.vertices_m[f[1]] - a).cross(mesh.vertices_m[f[2]] - a).normalized();
}

// Thesis joint (theta 30 deg, beta 0.03): each rail end is a hexahedron of
// six planar quads, two triangles each: top 2, cut 2, two sides 4, end 2,
// bottom 2 = 12 (the count the mesh tests assert for the whole solid).
TEST(FaceGroups, ARailEndSplitsIntoItsFiveFaces) {
  const RailJointMesh rails = build_rail_joint_mesh(JointParams{});
  const auto groups = split_by_face_tag(rails.incoming);
  std::map<std::string, const TriangleMesh*> by_name;
  for (const auto& [tag, group] : groups) by_name[to_string(tag)] = &group;
  ASSERT_EQ(by_name.size(), 5u);
  const std::map<std::string, std::size_t> triangles = {{"top", 2}, {"cut", 2}, {"side", 4}, {"end", 2}, {"bottom", 2}};
  for (const auto& [name, count] : triangles) {
    ASSERT_TRUE(by_name.contains(name)) << name;
    EXPECT_EQ(by_name[name]->triangles.size(), count) << name;
  }
  // A quad has 4 corners, two quads 8: each group keeps only what it uses.
  EXPECT_EQ(by_name["top"]->vertices_m.size(), 4u);
  EXPECT_EQ(by_name["side"]->vertices_m.size(), 8u);
  // The far end is the rectangle 2 b_t wide and d deep (L 1 m, b_t 20 mm, depth
  // at the end d plus the top's rise there): by hand, width x height.
  const JointParams joint;
  const double end_height = joint.depth_m + std::tan(0.015) * joint.length_m / 2.0;
  EXPECT_NEAR(surface_area_m2(*by_name["end"]), 2.0 * joint.half_width_m * end_height, 1e-15);

  // Outward normals by face, from the geometry: the incoming top falls
  // towards the joint, n = (sin(beta/2), 0, cos(beta/2)); the cut x = y cot(theta)
  // faces the joint, n = (sin(theta), -cos(theta), 0); the far end faces -x.
  const double half_beta = 0.015, theta = std::numbers::pi / 6.0;
  for (std::size_t t = 0; t < 2; ++t) {
    EXPECT_LT((unit_normal(*by_name["top"], t) - Eigen::Vector3d(std::sin(half_beta), 0, std::cos(half_beta))).norm(),
              1e-12);
    EXPECT_LT((unit_normal(*by_name["cut"], t) - Eigen::Vector3d(std::sin(theta), -std::cos(theta), 0)).norm(), 1e-12);
    EXPECT_LT((unit_normal(*by_name["end"], t) - Eigen::Vector3d(-1, 0, 0)).norm(), 1e-12);
    EXPECT_LT((unit_normal(*by_name["bottom"], t) - Eigen::Vector3d(0, 0, -1)).norm(), 1e-12);
  }
}

// The signed volume is a sum over triangles with absolute coordinates, so
// the groups' contributions add up to the solid's exactly (up to round-off).
TEST(FaceGroups, GroupsHoldEveryTriangleOnce) {
  WheelParams wheel;
  wheel.width_m = 0.03;
  for (const TriangleMesh& mesh : {build_rail_joint_mesh(JointParams{}).outgoing, build_wheel_mesh(wheel, 24)}) {
    std::size_t triangles = 0;
    double volume = 0.0;
    for (const auto& [tag, group] : split_by_face_tag(mesh)) {
      triangles += group.triangles.size();
      volume += signed_volume_m3(group);
      for (const FaceTag t : group.tags) EXPECT_EQ(t, tag);
    }
    EXPECT_EQ(triangles, mesh.triangles.size());
    EXPECT_NEAR(volume, signed_volume_m3(mesh), 1e-12 * signed_volume_m3(mesh));
  }
  const auto wheel_groups = split_by_face_tag(build_wheel_mesh(wheel, 24));
  ASSERT_EQ(wheel_groups.size(), 2u);  // the rim, and the two side faces in one group
  EXPECT_STREQ(to_string(wheel_groups[0].first), "rim");
  EXPECT_STREQ(to_string(wheel_groups[1].first), "face");
}

}  // namespace
}  // namespace railjoint
