// The side view's section of the rails through the wheel's width: closed,
// outward, the right volume, and refusing shapes it cannot cut.

#include <cmath>
#include <iostream>
#include <stdexcept>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "geometry/rail_joint_mesh.h"
#include "renders/slab_section.h"

namespace railjoint {
namespace {

// Unit cube [0, 1]^3, 12 outward triangles.
TriangleMesh unit_cube() {
  TriangleMesh m;
  for (int i = 0; i < 8; ++i) m.vertices_m.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& f : faces) {
    m.triangles.emplace_back(f[0], f[1], f[2]);
    m.triangles.emplace_back(f[0], f[2], f[3]);
    m.tags.insert(m.tags.end(), 2, FaceTag::top);
  }
  return m;
}

// A closed surface encloses the same volume wherever the origin is, and its
// area vectors sum to zero (the integral of n dA over a closed surface). The
// section faces meet the clipped faces with T-junctions (the section polygon
// keeps only its corners), so edges are not matched one to one; these two
// integral properties hold all the same.
bool closed(const TriangleMesh& m) {
  TriangleMesh shifted = m;
  for (auto& v : shifted.vertices_m) v += Eigen::Vector3d(0.3, -0.7, 1.1);
  Eigen::Vector3d area = Eigen::Vector3d::Zero();
  double scale = 0.0;
  for (const auto& t : m.triangles) {
    const Eigen::Vector3d n = (m.vertices_m[static_cast<std::size_t>(t[1])] - m.vertices_m[static_cast<std::size_t>(t[0])])
                                  .cross(m.vertices_m[static_cast<std::size_t>(t[2])] - m.vertices_m[static_cast<std::size_t>(t[0])]);
    area += n;
    scale += n.norm();
  }
  const double volume = signed_volume_m3(m), moved = signed_volume_m3(shifted);
  std::cout << "  closed? area vector sum " << area.norm() << " of " << scale << ", volume " << volume
            << " -> " << moved << " when moved\n";
  // Rounding only: 1e-12 of the summed areas and of the moved volume.
  return area.norm() <= 1e-12 * scale && std::abs(volume - moved) <= 1e-12 * (1.0 + scale);
}

TEST(SlabSection, CubeCutToASlabIsAClosedBoxOfTheSlabsVolume) {
  const TriangleMesh cut = cut_convex_solid_to_slab(unit_cube(), 0.25, 0.5);
  const double volume = signed_volume_m3(cut);
  std::cout << cut.triangles.size() << " triangles, volume " << volume << "\n";
  EXPECT_NEAR(volume, 0.25, 1e-12);  // 1 x 0.25 x 1
  EXPECT_TRUE(closed(cut));
  int sections = 0;
  for (std::size_t i = 0; i < cut.triangles.size(); ++i) {
    const Eigen::Vector3i& t = cut.triangles[i];
    for (int j = 0; j < 3; ++j) {
      const double y = cut.vertices_m[static_cast<std::size_t>(t[j])].y();
      EXPECT_GE(y, 0.25);
      EXPECT_LE(y, 0.5);
    }
    const Eigen::Vector3d n = (cut.vertices_m[t[1]] - cut.vertices_m[t[0]]).cross(cut.vertices_m[t[2]] - cut.vertices_m[t[0]]);
    if (cut.tags[i] == FaceTag::side) {
      ++sections;
      // Outward: -y on y = 0.25, +y on y = 0.5.
      const double y = cut.vertices_m[t[0]].y();
      EXPECT_GT(n.y() * (y < 0.3 ? -1.0 : 1.0), 0.0);
    }
  }
  EXPECT_EQ(sections, 4);  // two unit squares, two triangles each
}

TEST(SlabSection, SlabHoldingTheWholeSolidOrTouchingAFaceAddsNothing) {
  const TriangleMesh whole = cut_convex_solid_to_slab(unit_cube(), -1.0, 2.0);
  EXPECT_NEAR(signed_volume_m3(whole), 1.0, 1e-12);
  EXPECT_EQ(whole.triangles.size(), 12u);
  // The planes lie on the faces y = 0 and y = 1: nothing is cut off, no section face is added.
  const TriangleMesh touching = cut_convex_solid_to_slab(unit_cube(), 0.0, 1.0);
  EXPECT_NEAR(signed_volume_m3(touching), 1.0, 1e-12);
  EXPECT_EQ(touching.triangles.size(), 12u);
}

TEST(SlabSection, SlabBesideTheSolidLeavesNothing) {
  EXPECT_TRUE(cut_convex_solid_to_slab(unit_cube(), 1.5, 2.0).triangles.empty());
}

TEST(SlabSection, RefusesNonConvexSolidsAndAnInvertedSlab) {
  // The cube with its top dented: a centre vertex at z = 0.5 fanned to the
  // top corners, which then lie above the planes of the dent's triangles.
  TriangleMesh dented = unit_cube();
  dented.triangles.erase(dented.triangles.begin() + 2, dented.triangles.begin() + 4);  // top face {4, 5, 7, 6}
  dented.tags.resize(dented.triangles.size());
  dented.vertices_m.emplace_back(0.5, 0.5, 0.5);
  const int centre = 8;
  for (const auto& [a, b] : {std::pair{4, 5}, std::pair{5, 7}, std::pair{7, 6}, std::pair{6, 4}}) {
    dented.triangles.emplace_back(a, b, centre);
    dented.tags.push_back(FaceTag::top);
  }
  EXPECT_NEAR(signed_volume_m3(dented), 1.0 - 0.5 / 3.0, 1e-12);  // cube minus the pyramid of height 0.5
  EXPECT_THROW(cut_convex_solid_to_slab(dented, 0.2, 0.4), std::invalid_argument);
  EXPECT_THROW(cut_convex_solid_to_slab(unit_cube(), 0.5, 0.4), std::invalid_argument);
}

// The incoming rail of the thesis's joint (theta 30 deg, beta 0.03, L = 1 m,
// depth 50 mm) between y1 = 14.5 mm and y2 = 15.5 mm, the section the side
// view draws under a 1 mm wheel at y_w = 15 mm. At lateral y the rail runs
// from x = -L/2 to the cut x = y cot(theta), between z = -depth and the top
// z = -t x (t = tan(beta/2)): its cross-section area is
//   A(y) = depth (c + L/2) - t (c^2 - L^2/4) / 2,   c = y cot(theta),
// a quadratic in y, so Simpson's rule over [y1, y2] gives the volume exactly.
TEST(SlabSection, RailCutToTheWheelsWidthHasTheSectionVolume) {
  const JointParams joint;
  const RailJointMesh rails = build_rail_joint_mesh(joint);
  const double y1 = 0.0145, y2 = 0.0155, L = joint.length_m, depth = joint.depth_m;
  const double t = std::tan(joint.beta_rad / 2.0), cot = 1.0 / std::tan(joint.theta_rad);
  auto area = [&](double y) {
    const double c = y * cot;
    return depth * (c + L / 2.0) - t * (c * c - L * L / 4.0) / 2.0;
  };
  const double expected = (y2 - y1) / 6.0 * (area(y1) + 4.0 * area((y1 + y2) / 2.0) + area(y2));
  const TriangleMesh cut = cut_convex_solid_to_slab(rails.incoming, y1, y2);
  const double volume = signed_volume_m3(cut);
  std::cout << "incoming rail section: " << cut.triangles.size() << " triangles, volume " << volume
            << " m^3, expected " << expected << " m^3\n";
  // Rounding only: the volume sums products of coordinates of order 1 m.
  EXPECT_NEAR(volume, expected, 1e-12);
  EXPECT_TRUE(closed(cut));
}

}  // namespace
}  // namespace railjoint
