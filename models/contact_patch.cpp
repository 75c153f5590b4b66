#include "models/contact_patch.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace railjoint {

const char* to_string(PatchShape shape) {
  switch (shape) {
    case PatchShape::ellipse: return "ellipse";
    case PatchShape::polygon: return "polygon";
    case PatchShape::rectangle: return "rectangle";
  }
  return "?";
}

double patch_area_m2(const ContactPatch& patch) {
  const double a = patch.length_m;
  const double b = patch.width_m;
  switch (patch.shape) {
    case PatchShape::ellipse: return std::numbers::pi * a * b / 4.0;
    case PatchShape::polygon: {
      const double n = patch.vertices;
      return 0.5 * n * (a / 2.0) * (b / 2.0) * std::sin(2.0 * std::numbers::pi / n);
    }
    case PatchShape::rectangle: return a * b;
  }
  return 0.0;
}

Eigen::Vector2d patch_centre_m(const ContactPatch& patch, double x_front_m) {
  return {x_front_m - patch.length_m / 2.0, patch.width_m / 2.0};
}

std::vector<Eigen::Vector2d> ellipse_outline_m(const ContactPatch& patch, double x_front_m, int count) {
  const Eigen::Vector2d centre = patch_centre_m(patch, x_front_m);
  std::vector<Eigen::Vector2d> outline;
  outline.reserve(static_cast<std::size_t>(count));
  // The thesis's create_polygon: phi = 2 pi k / n from 0, vertex k at
  // centre + (a/2 cos phi, b/2 sin phi); counter-clockwise.
  for (int k = 0; k < count; ++k) {
    const double phi = 2.0 * std::numbers::pi * k / count;
    outline.emplace_back(centre.x() + patch.length_m / 2.0 * std::cos(phi), centre.y() + patch.width_m / 2.0 * std::sin(phi));
  }
  return outline;
}

std::vector<Eigen::Vector2d> patch_outline_m(const ContactPatch& patch, double x_front_m, int ellipse_points) {
  return patch.shape == PatchShape::ellipse ? ellipse_outline_m(patch, x_front_m, ellipse_points)
                                            : patch_polygon_m(patch, x_front_m);
}

std::vector<Eigen::Vector2d> patch_polygon_m(const ContactPatch& patch, double x_front_m) {
  if (patch.shape == PatchShape::rectangle) {
    const double x0 = x_front_m - patch.length_m;
    return {Eigen::Vector2d(x0, 0.0), Eigen::Vector2d(x_front_m, 0.0), Eigen::Vector2d(x_front_m, patch.width_m),
            Eigen::Vector2d(x0, patch.width_m)};
  }
  return ellipse_outline_m(patch, x_front_m, patch.vertices);
}

PatchSpan patch_span_m(const ContactPatch& patch, const Eigen::Vector2d& n) {
  if (patch.shape == PatchShape::ellipse) {
    // Support function of an ellipse: h = sqrt((a/2 n_x)^2 + (b/2 n_y)^2) about its centre.
    const double h = std::hypot(patch.length_m / 2.0 * n.x(), patch.width_m / 2.0 * n.y());
    const double c = n.dot(patch_centre_m(patch, 0.0));
    return {c - h, c + h};
  }
  PatchSpan span{std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  for (const Eigen::Vector2d& p : patch_polygon_m(patch, 0.0)) {
    span.min_m = std::min(span.min_m, n.dot(p));
    span.max_m = std::max(span.max_m, n.dot(p));
  }
  return span;
}

}  // namespace railjoint
