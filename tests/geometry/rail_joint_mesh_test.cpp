// The rail-joint solids: closed, outward, coarse, and on the geometry of
// models/DESIGN.md "Coordinates and symbols" (restated in joint_cases.h), over square,
// shallow, flat, gapped and step joints.

#include "geometry/rail_joint_mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>

#include "support/input_error.h"
#include "tests/geometry/joint_cases.h"
#include "tests/geometry/mesh_checks.h"

namespace railjoint {
namespace {

using test::JointCase;

// Coordinates are up to 1.5 m and every vertex is a few floating-point
// operations from the formula: deviations of a few ulp (3.3e-16 m at 1.5 m);
// the largest seen is 5.6e-17 m. 2e-15 m is ten times a few ulp and far below
// any real mistake (a wrong sign moves points by tan(beta/2) x ~ 1e-3 m).
constexpr double kPositionTol_m = 2e-15;

class RailJointMeshTest : public testing::TestWithParam<JointCase> {
 protected:
  const JointParams& joint() const { return GetParam().joint; }
  std::array<TriangleMesh, 2> rails() const {
    RailJointMesh mesh = build_rail_joint_mesh(joint());
    return {mesh.incoming, mesh.outgoing};
  }
};

TEST_P(RailJointMeshTest, GeometryIsValidForTheDefaultWheel) {
  EXPECT_NO_THROW(check_joint_geometry(joint(), WheelParams{}));
}

TEST_P(RailJointMeshTest, ClosedManifoldOfTwelveTriangles) {
  for (const TriangleMesh& rail : rails()) {
    std::cout << rail.triangles.size() << " triangles, " << rail.vertices_m.size() << " vertices\n";
    EXPECT_EQ(test::manifold_defects(rail), "");
    // A planar top over a quadrilateral footprint: a hexahedron, 8 corners,
    // 6 quads of 2 triangles: top 2, bottom 2, sides 4, end 2, cut 2.
    EXPECT_EQ(rail.vertices_m.size(), 8u);
    ASSERT_EQ(rail.triangles.size(), 12u);
    const auto count = [&](FaceTag tag) { return std::count(rail.tags.begin(), rail.tags.end(), tag); };
    EXPECT_EQ(count(FaceTag::top), 2);
    EXPECT_EQ(count(FaceTag::bottom), 2);
    EXPECT_EQ(count(FaceTag::side), 4);
    EXPECT_EQ(count(FaceTag::end), 2);
    EXPECT_EQ(count(FaceTag::cut), 2);
  }
}

TEST_P(RailJointMeshTest, VolumeMatchesHandDerivation) {
  const auto meshes = rails();
  for (int rail = 0; rail < 2; ++rail) {
    const double volume = signed_volume_m3(meshes[rail]);
    const double expected = test::expected_volume(joint(), rail);
    std::cout << "rail " << rail << ": volume " << volume << " m^3, hand-derived " << expected
              << ", relative deviation " << (volume - expected) / expected << "\n";
    // Round-off only: 2.4e-16 relative seen, tolerance about ten times that.
    EXPECT_NEAR(volume, expected, 2e-15 * expected);
  }
}

// Each tagged triangle faces where its face of the solid faces: this catches
// inverted winding and triangles assigned to the wrong face.
TEST_P(RailJointMeshTest, NormalsMatchTags) {
  const JointParams& j = joint();
  const double t = test::tan_half_beta(j);
  const double k = test::cot_theta(j);
  const auto meshes = rails();
  double worst = 0.0;
  for (int rail = 0; rail < 2; ++rail) {
    const double side = rail == 0 ? -1.0 : 1.0;  // incoming ends at its cut (+x), outgoing starts there
    const TriangleMesh& mesh = meshes[rail];
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
      const Eigen::Vector3i& tri = mesh.triangles[i];
      const double centroid_y = (mesh.vertices_m[tri[0]] + mesh.vertices_m[tri[1]] + mesh.vertices_m[tri[2]]).y() / 3.0;
      Eigen::Vector3d expected;
      switch (mesh.tags[i]) {
        case FaceTag::top:  // z = side t x has the upward normal (-side t, 0, 1)
          expected = Eigen::Vector3d(-side * t, 0.0, 1.0).normalized();
          break;
        case FaceTag::bottom:
          expected = -Eigen::Vector3d::UnitZ();
          break;
        case FaceTag::side:
          expected = Eigen::Vector3d(0.0, centroid_y > 0.0 ? 1.0 : -1.0, 0.0);
          break;
        case FaceTag::end:
          expected = Eigen::Vector3d(side, 0.0, 0.0);
          break;
        case FaceTag::cut:  // plane x - k y = const, pointing out of the rail: towards +x for the incoming one
          expected = -side * Eigen::Vector3d(1.0, -k, 0.0).normalized();
          break;
        default:
          ADD_FAILURE() << "rail triangle tagged as a wheel face";
          continue;
      }
      const double deviation = (test::unit_normal(mesh, i) - expected).norm();
      worst = std::max(worst, deviation);
      EXPECT_LT(deviation, 1e-14) << "rail " << rail << " triangle " << i << " tag " << int(mesh.tags[i]);
    }
  }
  std::cout << "largest normal deviation " << worst << "\n";  // 1e-15 seen: round-off of the cross product
}

// Every vertex lies on the planes of the faces it belongs to.
TEST_P(RailJointMeshTest, FaceVerticesLieOnTheirPlanes) {
  const JointParams& j = joint();
  const auto meshes = rails();
  double worst = 0.0;
  for (int rail = 0; rail < 2; ++rail) {
    const TriangleMesh& mesh = meshes[rail];
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
      for (int c = 0; c < 3; ++c) {
        const Eigen::Vector3d& v = mesh.vertices_m[mesh.triangles[i][c]];
        double deviation = 0.0;
        switch (mesh.tags[i]) {
          case FaceTag::top:
            deviation = v.z() - test::expected_top(j, rail, v.x());
            break;
          case FaceTag::bottom:
            deviation = v.z() + j.depth_m;
            break;
          case FaceTag::side:
            deviation = std::abs(v.y()) - j.half_width_m;
            break;
          case FaceTag::end:
            deviation = v.x() - (rail == 0 ? -1.0 : 1.0) * j.length_m / 2.0;
            break;
          case FaceTag::cut:
            deviation = v.x() - test::expected_cut_x(j, v.y(), rail);
            break;
          default:
            break;
        }
        worst = std::max(worst, std::abs(deviation));
        EXPECT_LT(std::abs(deviation), kPositionTol_m) << "rail " << rail << " triangle " << i << " corner " << c;
      }
    }
  }
  std::cout << "largest distance of a vertex from its face plane " << worst << " m\n";
}

// Points inside the top triangles (not only corners) follow the rail-top formula.
TEST_P(RailJointMeshTest, TopSurfaceFollowsTheProfileInside) {
  const JointParams& j = joint();
  const auto meshes = rails();
  const std::array<Eigen::Vector3d, 4> weights = {Eigen::Vector3d(1, 1, 1) / 3.0, Eigen::Vector3d(0.7, 0.2, 0.1),
                                                  Eigen::Vector3d(0.05, 0.9, 0.05), Eigen::Vector3d(0.1, 0.3, 0.6)};
  double worst = 0.0;
  for (int rail = 0; rail < 2; ++rail) {
    const TriangleMesh& mesh = meshes[rail];
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
      if (mesh.tags[i] != FaceTag::top) continue;
      for (const Eigen::Vector3d& w : weights) {
        const Eigen::Vector3i& tri = mesh.triangles[i];
        const Eigen::Vector3d p =
            w[0] * mesh.vertices_m[tri[0]] + w[1] * mesh.vertices_m[tri[1]] + w[2] * mesh.vertices_m[tri[2]];
        const double deviation = p.z() - test::expected_top(j, rail, p.x());
        worst = std::max(worst, std::abs(deviation));
        EXPECT_LT(std::abs(deviation), kPositionTol_m);
      }
    }
  }
  std::cout << "largest top-surface deviation " << worst << " m\n";
}

// Height of the top edge of rail `rail`'s cut face at lateral y, read off the
// mesh: the cut face's two top corners (y = -b_t and +b_t), interpolated.
double cut_edge_height(const TriangleMesh& mesh, double y) {
  std::vector<Eigen::Vector3d> corners;
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    if (mesh.tags[i] != FaceTag::cut) continue;
    for (int c = 0; c < 3; ++c) {
      const Eigen::Vector3d& v = mesh.vertices_m[mesh.triangles[i][c]];
      const bool known = std::any_of(corners.begin(), corners.end(), [&](const Eigen::Vector3d& u) { return u == v; });
      if (!known) corners.push_back(v);
    }
  }
  EXPECT_EQ(corners.size(), 4u);
  std::sort(corners.begin(), corners.end(), [](const auto& a, const auto& b) { return a.z() > b.z(); });
  const Eigen::Vector3d& lo = corners[0].y() < corners[1].y() ? corners[0] : corners[1];
  const Eigen::Vector3d& hi = corners[0].y() < corners[1].y() ? corners[1] : corners[0];
  return lo.z() + (hi.z() - lo.z()) * (y - lo.y()) / (hi.y() - lo.y());
}

// The step at the cut (gap-free joints): 2 tan(beta/2) y cot(theta), up for
// y > 0 (models/DESIGN.md "Coordinates and symbols"); u0 for the step joint. With a gap both ends also sit at
// -+ s along the slope: the step is still 2 t y k (the rails' heights at
// y k - s and y k + s are t (s - y k) and t (y k + s)).
TEST_P(RailJointMeshTest, StepAtTheCut) {
  const JointParams& j = joint();
  const auto meshes = rails();
  double worst = 0.0;
  for (const double fraction : {-1.0, -0.7, -0.25, 0.0, 0.4, 0.93, 1.0}) {
    const double y = fraction * j.half_width_m;
    const double expected = test::is_step(j) ? j.step_height_m : 2.0 * test::tan_half_beta(j) * y * test::cot_theta(j);
    const double step = cut_edge_height(meshes[1], y) - cut_edge_height(meshes[0], y);
    worst = std::max(worst, std::abs(step - expected));
    EXPECT_NEAR(step, expected, kPositionTol_m) << "y = " << y;
  }
  std::cout << "largest deviation of the step at the cut " << worst << " m\n";
}

INSTANTIATE_TEST_SUITE_P(Joints, RailJointMeshTest, testing::ValuesIn(test::joint_cases()),
                         [](const auto& joint_case) { return joint_case.param.name; });

// ---------------------------------------------------------------------------
// check_joint_geometry: every rejection names the scene key.

std::string rejected_key(const JointParams& joint, const WheelParams& wheel = {}) {
  try {
    check_joint_geometry(joint, wheel);
  } catch (const InputError& error) {
    std::cout << error.key() << ": " << error.what() << "\n";
    return error.key();
  }
  return "(accepted)";
}

TEST(CheckJointGeometry, RejectsBadSizesAndAngles) {
  JointParams j;
  j.length_m = -1.0;
  EXPECT_EQ(rejected_key(j), "joint.length");
  j = {};
  j.depth_m = 0.0;
  EXPECT_EQ(rejected_key(j), "joint.depth");
  j = {};
  j.gap_m = -0.001;
  EXPECT_EQ(rejected_key(j), "joint.gap");
  j = {};
  j.half_width_m = 0.0;
  EXPECT_EQ(rejected_key(j), "joint.half_width");
  j = {};
  j.theta_rad = 0.0;
  EXPECT_EQ(rejected_key(j), "joint.theta_deg");
  j.theta_rad = test::degrees(91.0);
  EXPECT_EQ(rejected_key(j), "joint.theta_deg");
  WheelParams off_head;
  off_head.lateral_m = 0.021;  // b_t = 20 mm
  EXPECT_EQ(rejected_key(JointParams{}, off_head), "wheel.y");
}

// Thesis joint (theta 30 deg, L = 1 m, b_t = 20 mm): the cut reaches
// b_t cot(30 deg) = 34.64 mm either side of x = 0, each rail end is shorter by
// the shift s = g / (2 sin 30 deg) = g, so the shorter rail end vanishes when
// s = L/2 - 34.64 mm, g = 0.4654 m.
TEST(CheckJointGeometry, RejectsAGapThatSwallowsARail) {
  JointParams j;
  const double g_max = 2.0 * std::sin(j.theta_rad) * (0.5 - 0.02 / std::tan(j.theta_rad));
  j.gap_m = g_max * 1.001;
  EXPECT_EQ(rejected_key(j), "joint.gap");
  j.gap_m = g_max * 0.999;  // rails exist but are far too short for the wheel
  EXPECT_EQ(rejected_key(j), "joint.length");
}

// The documented length rule: L >= 2 (b_t cot(theta) + s + max(run_in, run_out)),
// run_in = 0.05 m + R sin(beta/2), run_out = 0.05 m + min(R, sqrt(2 R h) + R sin(beta/2)),
// h = 2 tan(beta/2) (b_t cot(theta) + s): the mismatch at the far rail's corner,
// which the gap shift s moves up the slope (|u0| for the step joint, with run_in = 0.05 m).
TEST(CheckJointGeometry, LengthRuleBoundary) {
  const WheelParams wheel;  // R = 0.475 m
  const double R = wheel.radius_m;
  for (const JointCase& c : test::joint_cases()) {
    JointParams j = c.joint;
    const double k = test::cot_theta(j), t = test::tan_half_beta(j), b = j.half_width_m;
    const double slope_lead = test::is_step(j) ? 0.0 : R * std::sin(j.beta_rad / 2.0);
    const double h = test::is_step(j) ? std::abs(j.step_height_m) : 2.0 * t * (b * k + test::half_gap_along_x(j));
    const double run_in = 0.05 + slope_lead;
    const double run_out = 0.05 + std::min(R, std::sqrt(2.0 * R * h) + slope_lead);
    const double length_min = 2.0 * (b * k + test::half_gap_along_x(j) + std::max(run_in, run_out));
    std::cout << c.name << ": L_min = " << length_min << " m\n";
    j.length_m = length_min * (1.0 + 1e-9);
    EXPECT_EQ(rejected_key(j), "(accepted)") << c.name;
    j.length_m = length_min * (1.0 - 1e-9);
    EXPECT_EQ(rejected_key(j), "joint.length") << c.name;
  }
  // The shallow 1-deg joint with a 1 m rail: the cut alone (2.29 m) does not fit.
  JointParams shallow;
  shallow.theta_rad = test::degrees(1.0);
  EXPECT_EQ(rejected_key(shallow), "joint.length");
}

// The bottom must lie below the lowest top point. Thesis joint: the incoming
// top is lowest at its cut corner y = b_t, x = b_t cot(30 deg) = 34.64 mm,
// z = -tan(0.015) * 34.64 mm = -0.5197 mm. Step down 2 mm: the outgoing top at
// z = -2 mm.
TEST(CheckJointGeometry, DepthBoundary) {
  JointParams j;
  const double lowest = -std::tan(j.beta_rad / 2.0) * j.half_width_m / std::tan(j.theta_rad);
  j.depth_m = -lowest * 0.999;
  EXPECT_EQ(rejected_key(j), "joint.depth");
  j.depth_m = -lowest * 1.001;
  EXPECT_EQ(rejected_key(j), "(accepted)");

  j = {};
  j.kind = JointKind::step;
  j.step_height_m = -0.002;
  j.depth_m = 0.0019;
  EXPECT_EQ(rejected_key(j), "joint.depth");
  j.depth_m = 0.0021;
  EXPECT_EQ(rejected_key(j), "(accepted)");
  j.step_height_m = 0.5;  // u0 >= R = 0.475 m
  EXPECT_EQ(rejected_key(j), "joint.step_height");
}

TEST(CheckJointGeometry, MessageGivesTheAllowedValue) {
  JointParams j;
  j.theta_rad = test::degrees(1.0);
  j.length_m = 2.5;  // holds the 2.29 m cut, not the run-up and run-out
  try {
    check_joint_geometry(j, WheelParams{});
    FAIL() << "accepted";
  } catch (const InputError& error) {
    const std::string message = error.what();
    std::cout << message << "\n";
    EXPECT_EQ(error.key(), "joint.length");
    EXPECT_NE(message.find(">= 2.7"), std::string::npos) << "L_min = 2.77 m by the rule above";
    EXPECT_NE(message.find("got 2.5 m"), std::string::npos);
  }
}

}  // namespace
}  // namespace railjoint
