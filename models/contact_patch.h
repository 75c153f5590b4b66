#pragma once
// The contact patch of the local model (thesis sections 5.2 and 6.1): a
// predetermined (or Hertzian, models/hertz_contact.h) footprint of full
// length a along the track and width b across it, sliding over the end-post
// gap. Three shapes:
//   ellipse    the exact ellipse with semi-axes a/2 and b/2 (default);
//   polygon    the thesis's n-gon: the ellipse sampled at n equally spaced
//              parameter angles (appendix code, create_polygon), whose area
//              n/2 (a/2)(b/2) sin(2 pi/n) depends on n;
//   rectangle  a x b (figures 5.2-5.4).
// In the thesis's frame the patch spans 0 <= y <= b and its front is at
// x_front: the ellipse's centre is (x_front - a/2, b/2).

#include <vector>

#include <Eigen/Core>

namespace railjoint {

enum class PatchShape { ellipse, polygon, rectangle };

const char* to_string(PatchShape shape);

struct ContactPatch {
  PatchShape shape = PatchShape::ellipse;
  double length_m = 0.016;  ///< a: full length along the track [m] (table 6.1: 16 mm)
  double width_m = 0.012;   ///< b: full width across the track [m] (table 6.1: 12 mm)
  int vertices = 100;       ///< polygon only: n (table 6.1: 100)
};

/// A0: the whole patch's area [m^2] (pi a b / 4, n/2 (a/2)(b/2) sin(2 pi / n), or a b).
double patch_area_m2(const ContactPatch& patch);

/// Centre of the patch whose front is at x_front [m].
Eigen::Vector2d patch_centre_m(const ContactPatch& patch, double x_front_m);

/// Outline of a polygon or rectangle patch, counter-clockwise, not closed [m]:
/// the thesis's vertices (an ellipse has none; see ellipse_outline_m).
std::vector<Eigen::Vector2d> patch_polygon_m(const ContactPatch& patch, double x_front_m);

/// `count` points on the exact ellipse's outline, counter-clockwise (for drawing).
std::vector<Eigen::Vector2d> ellipse_outline_m(const ContactPatch& patch, double x_front_m, int count);

/// The outline of any shape, for drawing and clipping: a polygon's or
/// rectangle's vertices, or `ellipse_points` points on the exact ellipse.
std::vector<Eigen::Vector2d> patch_outline_m(const ContactPatch& patch, double x_front_m, int ellipse_points = 128);

/// Extent of the patch along a unit direction n, at x_front = 0: the smallest
/// and largest n.p over the patch [m]. A patch front at x_front shifts both by
/// n.x * x_front.
struct PatchSpan {
  double min_m = 0.0;
  double max_m = 0.0;
};
PatchSpan patch_span_m(const ContactPatch& patch, const Eigen::Vector2d& unit_direction);

}  // namespace railjoint
