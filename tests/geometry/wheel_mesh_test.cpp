// The wheel render mesh and where the wheel rests on the incoming rail.

#include "geometry/wheel_mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numbers>

#include "geometry/wheel_placement.h"
#include "tests/geometry/joint_cases.h"
#include "tests/geometry/mesh_checks.h"

namespace railjoint {
namespace {

struct WheelCase {
  int segments;
  double width_m;
};

std::ostream& operator<<(std::ostream& out, const WheelCase& c) {
  return out << c.segments << " segments, b_w = " << c.width_m << " m";
}

class WheelMeshTest : public testing::TestWithParam<WheelCase> {};

TEST_P(WheelMeshTest, ClosedPrismOfTheRightSize) {
  const auto [segments, width] = GetParam();
  WheelParams wheel;
  wheel.width_m = width;
  const TriangleMesh mesh = build_wheel_mesh(wheel, segments);
  const double R = wheel.radius_m;
  const double w = std::max(width, 0.01);  // default min_width 10 mm

  EXPECT_EQ(test::manifold_defects(mesh), "");
  // Tread: one quad (2 triangles) per side; each disc: a fan of `segments` triangles.
  EXPECT_EQ(mesh.triangles.size(), 4u * segments);
  EXPECT_EQ(mesh.vertices_m.size(), 2u * segments + 2u);
  EXPECT_EQ(std::count(mesh.tags.begin(), mesh.tags.end(), FaceTag::wheel_rim), 2 * segments);
  EXPECT_EQ(std::count(mesh.tags.begin(), mesh.tags.end(), FaceTag::wheel_face), 2 * segments);

  // Regular N-gon of circumradius R: area N/2 R^2 sin(2 pi / N); times the width.
  const double expected = segments / 2.0 * R * R * std::sin(2.0 * std::numbers::pi / segments) * w;
  const double volume = signed_volume_m3(mesh);
  std::cout << segments << " segments, width " << w << " m: volume " << volume << " m^3, expected " << expected
            << ", relative deviation " << (volume - expected) / expected << "\n";
  // Round-off grows with the N terms and N sin/cos: up to N * 5.5e-17 seen; N * 6e-16 allowed.
  EXPECT_NEAR(volume, expected, segments * 6e-16 * expected);

  const test::Box box = test::bounding_box(mesh);
  EXPECT_NEAR(box.max.y(), w / 2.0, 1e-16);
  EXPECT_NEAR(box.min.y(), -w / 2.0, 1e-16);
  double worst = 0.0;
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    const Eigen::Vector3i& t = mesh.triangles[i];
    const Eigen::Vector3d centroid = (mesh.vertices_m[t[0]] + mesh.vertices_m[t[1]] + mesh.vertices_m[t[2]]) / 3.0;
    const Eigen::Vector3d n = test::unit_normal(mesh, i);
    if (mesh.tags[i] == FaceTag::wheel_rim) {
      // Tread normals are radial (no y part) and point away from the axle.
      EXPECT_NEAR(n.y(), 0.0, 1e-12);
      EXPECT_GT(n.dot(Eigen::Vector3d(centroid.x(), 0.0, centroid.z())), 0.0);
      for (int c = 0; c < 3; ++c) {
        const Eigen::Vector3d& v = mesh.vertices_m[t[c]];
        worst = std::max(worst, std::abs(std::hypot(v.x(), v.z()) - R));
      }
    } else {
      EXPECT_NEAR(std::abs(n.y()), 1.0, 1e-12);
      EXPECT_GT(n.y() * centroid.y(), 0.0) << "disc normal points out of the wheel";
    }
  }
  std::cout << "largest tread-vertex radius error " << worst << " m\n";
  EXPECT_LT(worst, 1e-15);  // R cos, R sin: a few ulp of 0.475 m (5.6e-17 m seen)
}

INSTANTIATE_TEST_SUITE_P(Wheels, WheelMeshTest,
                         testing::Values(WheelCase{3, 0.0}, WheelCase{8, 0.005}, WheelCase{64, 0.0},
                                         WheelCase{64, 0.13}, WheelCase{257, 0.02}));

// The wheel touching the incoming rail at x_c: its centre is R from the rail
// top along the top's normal. Thesis joint: top z = -t x with t = tan(0.015),
// so the centre is at distance (z + t x) / sqrt(1 + t^2) = R above that plane,
// R sin(beta/2) ahead of x_c. Step joint: straight above, z = R.
TEST(WheelPlacement, RestsOnTheIncomingRail) {
  const WheelParams wheel;
  const JointParams thesis;
  const double t = std::tan(thesis.beta_rad / 2.0);
  const Eigen::Vector3d c = wheel_centre_on_incoming_rail_m(thesis, wheel, -0.2);
  std::cout << "centre " << c.transpose() << "\n";
  EXPECT_NEAR((c.z() + t * c.x()) / std::sqrt(1.0 + t * t), wheel.radius_m, 1e-14);
  EXPECT_NEAR(c.x(), -0.2 + wheel.radius_m * std::sin(thesis.beta_rad / 2.0), 1e-14);
  EXPECT_EQ(c.y(), wheel.lateral_m);

  JointParams step;
  step.kind = JointKind::step;
  const Eigen::Vector3d s = wheel_centre_on_incoming_rail_m(step, wheel, -0.2);
  EXPECT_EQ(s, Eigen::Vector3d(-0.2, wheel.lateral_m, wheel.radius_m));
}

}  // namespace
}  // namespace railjoint
