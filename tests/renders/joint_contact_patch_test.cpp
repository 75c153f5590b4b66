// The local model's contact patch laid on the global joint
// (renders/joint_contact_patch.h): where it lands and how much of it lies
// over the end-post gap, against hand derivations and symmetries.

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "renders/joint_contact_patch.h"

namespace railjoint {
namespace {

// Table 6.1's patch (an ellipse 16 x 12 mm), N and v; the gap as given.
PressureInputs inputs(double gap_m, double theta_rad) {
  PressureInputs in;
  in.patch.length_m = 0.016;
  in.patch.width_m = 0.012;
  in.gap = EndPostGap{gap_m, theta_rad};
  return in;
}

TEST(JointContactPatch, OnASquareJointThePatchCentredOnTheGapHasTheHandDerivedReduction) {
  // theta = 90 deg, g = 6 mm: the gap is the strip |x| <= 3 mm at every y.
  // The ellipse x^2/8^2 + y^2/6^2 <= 1 (mm) centred on it keeps over the gap
  //   R = 2 * 6 * integral_{-3}^{3} sqrt(1 - x^2/64) dx = 96 (c sqrt(1 - c^2) + asin c), c = 3/8,
  //     = 96 (0.375 * 0.9270248 + 0.3843968) = 70.2754 mm^2,
  // and its front is 3 mm (half the gap) + 8 mm (half the patch) past the
  // gap's near edge: x_front = 11 mm.
  const PressureInputs in = inputs(0.006, std::numbers::pi / 2.0);
  const PatchPlacement p = place_contact_patch(in, {0.0, 0.0}, 0.020);
  EXPECT_NEAR(p.x_front_m, 0.011, 1e-12);
  const double c = 0.375;
  EXPECT_NEAR(p.state.reduction_area_m2, 96e-6 * (c * std::sqrt(1.0 - c * c) + std::asin(c)), 1e-12);
  // A0 = pi a b / 4 = 150.796 mm^2; P = N / (A0 - R).
  EXPECT_NEAR(p.state.pressure_Pa, in.normal_force_N / (std::numbers::pi * 0.016 * 0.012 / 4.0 - p.state.reduction_area_m2),
              1e-6 * p.state.pressure_Pa);
}

TEST(JointContactPatch, OnAnInclinedCutTheReductionIsSymmetricAboutTheGapsCentreLine) {
  // The gap's centre line is the cut x = y cot(theta) (models/parameters.h).
  // An ellipse and the gap's strip are both symmetric about a point of that
  // line, so a patch moved d ahead of it covers as much gap as one moved d
  // behind, and most when centred on it. A placement off by any shift along
  // x breaks the symmetry.
  const double theta = std::numbers::pi / 6.0;
  const PressureInputs in = inputs(0.006, theta);
  const double y_c = 0.004, x_line = y_c / std::tan(theta);
  const double centred = place_contact_patch(in, {x_line, y_c}, 0.020).state.reduction_area_m2;
  for (double d : {0.001, 0.004, 0.009}) {
    const double ahead = place_contact_patch(in, {x_line + d, y_c}, 0.020).state.reduction_area_m2;
    const double behind = place_contact_patch(in, {x_line - d, y_c}, 0.020).state.reduction_area_m2;
    EXPECT_NEAR(ahead, behind, 1e-12) << "d = " << d;
    EXPECT_LT(ahead, centred) << "d = " << d;
  }
  // The patch leaves the gap when its centre is g/2 + h from the cut's
  // centre line, measured along the cut's normal n = (sin theta, -cos theta);
  // h = sqrt((a/2 sin theta)^2 + (b/2 cos theta)^2) = sqrt(4^2 + 5.196^2) = 6.557 mm
  // is the ellipse's reach along n. A shift d along x moves it d sin theta
  // along n: clear at d = (3 + 6.557) / 0.5 = 19.11 mm.
  const double h = std::hypot(0.008 * std::sin(theta), 0.006 * std::cos(theta));
  const double d_clear = (0.003 + h) / std::sin(theta);
  for (double side : {-1.0, 1.0}) {
    // Clear: zero to round-off (areas here are 1e-4 m^2). 0.1 mm short of
    // clear: a sliver 0.05 mm deep, about 0.06 mm^2.
    EXPECT_NEAR(place_contact_patch(in, {x_line + side * (d_clear + 1e-4), y_c}, 0.020).state.reduction_area_m2, 0.0,
                1e-18);
    EXPECT_GT(place_contact_patch(in, {x_line + side * (d_clear - 1e-4), y_c}, 0.020).state.reduction_area_m2, 1e-8);
  }
}

TEST(JointContactPatch, APatchThatWouldOverhangTheRailHeadIsMovedOntoIt) {
  // b_t = 20 mm, b = 12 mm: the centre may be at most 14 mm off the head's
  // centre line; the local frame's origin is then at the patch's lower edge, 8 mm.
  const PressureInputs in = inputs(0.006, std::numbers::pi / 2.0);
  EXPECT_NEAR(place_contact_patch(in, {0.0, 0.015}, 0.020).local_origin_m.y(), 0.008, 1e-15);
  EXPECT_NEAR(place_contact_patch(in, {0.0, -0.019}, 0.020).local_origin_m.y(), -0.020, 1e-15);
  EXPECT_NEAR(place_contact_patch(in, {0.0, 0.010}, 0.020).local_origin_m.y(), 0.004, 1e-15);
}

TEST(JointContactPatch, TheRedTrianglesCoverTheReductionArea) {
  // The drawn pieces over the gap add up to R, and the whole patch to A0.
  const double theta = std::numbers::pi / 6.0;
  const PressureInputs in = inputs(0.006, theta);
  const PatchPlacement p = place_contact_patch(in, {0.003 / std::tan(theta) + 0.002, 0.003}, 0.020);
  double bearing = 0.0, over_gap = 0.0;
  const auto triangles = contact_patch_vertices(in, p, 0.0);
  for (std::size_t i = 0; i + 2 < triangles.size(); i += 3) {
    const Eigen::Vector3f u = triangles[i + 1].position_m - triangles[i].position_m;
    const Eigen::Vector3f v = triangles[i + 2].position_m - triangles[i].position_m;
    const double area = 0.5 * std::abs(static_cast<double>(u.x()) * v.y() - static_cast<double>(u.y()) * v.x());
    (triangles[i].position_m.z() > 0.0f ? over_gap : bearing) += area;
  }
  // float vertices (7 digits) and a 128-gon for the ellipse (A0 short by 0.04 %).
  EXPECT_NEAR(over_gap, p.state.reduction_area_m2, 2e-3 * p.state.reduction_area_m2);
  EXPECT_NEAR(bearing, std::numbers::pi * 0.016 * 0.012 / 4.0, 1e-3 * bearing);
  EXPECT_GT(p.state.reduction_area_m2, 0.0);
}

}  // namespace
}  // namespace railjoint
