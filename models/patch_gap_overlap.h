#pragma once
// The part of the contact patch over the end-post gap: the thesis's
// reduction area R (eq. 5.2, A = A0 - R) and its exact derivative with
// respect to the patch's travel, dR/dx_front, from which the rate of change
// of the pressure follows without differencing samples.
//
// Exact ellipse: an affine map (x, y) -> ((x - c_x)/(a/2), (y - c_y)/(b/2))
// turns the ellipse into the unit disc, keeps the parallelogram a
// parallelogram and scales every area by ab/4. The area of the unit disc
// inside a polygon is a sum over the polygon's edges (p, q) of the signed
// area of the disc inside the triangle (0, p, q): a triangle where the edge
// runs inside the disc, circular sectors where it runs outside.
// The derivative: moving the patch by dx moves the gap by -dx relative to
// it, and only the gap's boundary inside the patch sweeps area, so
// dR/dx_front = - sum over the gap's edges (counter-clockwise) of
// (fraction of the edge inside the patch) * (the edge's Delta y).
//
// Polygon and rectangle patches: the intersection through Boost.Geometry
// (built with BOOST_GEOMETRY_NO_ROBUSTNESS: no integer rescaling, so a
// fine polygon converges on the exact area as 1/n^2), and the same edge
// formula for the derivative with the edge pieces inside the patch from
// Boost.Geometry too.

#include <vector>

#include <Eigen/Core>

#include "models/contact_patch.h"
#include "models/end_post_gap.h"

namespace railjoint {

struct GapOverlap {
  double area_m2 = 0.0;             ///< R: patch area over the gap [m^2]
  double d_area_d_x_front_m = 0.0;  ///< dR/dx_front [m^2/m]
};

/// R and dR/dx_front for a patch whose front is at x_front [m] (any shape).
GapOverlap patch_gap_overlap(const ContactPatch& patch, const EndPostGap& gap, double x_front_m);

/// Exact area of the unit disc inside a simple polygon given counter-clockwise
/// (any number of vertices, convex or not; clockwise gives the negative).
double unit_disc_polygon_area(const std::vector<Eigen::Vector2d>& polygon);

/// Area of the intersection of two simple polygons (counter-clockwise, not
/// closed) through Boost.Geometry [m^2].
double polygon_intersection_area_m2(const std::vector<Eigen::Vector2d>& a, const std::vector<Eigen::Vector2d>& b);

/// The pieces of `outline` over the gap (for drawing), each counter-clockwise, not closed.
std::vector<std::vector<Eigen::Vector2d>> outline_over_gap_m(const std::vector<Eigen::Vector2d>& outline,
                                                             const EndPostGap& gap, double width_m);

}  // namespace railjoint
