#pragma once
// The thesis's own method for the local model (its appendix code and section
// 5.2), written again here as an independent reference for the tests: the
// n-gon patch of create_polygon, its intersection with the gap by clipping
// against the parallelogram's edges one by one (section 5.2: intersect the
// line segments, keep what lies inside), the shoelace formula (eq. 5.3), and
// numpy.gradient's differences for the rate (get_derivative: central in the
// interior, one-sided at both ends). Nothing from models/ but the plain
// parameter structs.

#include <cmath>
#include <numbers>
#include <vector>

#include <Eigen/Core>

namespace railjoint::thesis_reference {

using Polygon = std::vector<Eigen::Vector2d>;

/// create_polygon(a, b, n, x): the ellipse with centre (x - a/2, b/2) sampled
/// at phi = 2 pi k / n, k = 0..n-1 (the thesis closes it with k = n).
inline Polygon thesis_polygon(double a, double b, int n, double x_front) {
  Polygon p;
  for (int k = 0; k < n; ++k) {
    const double phi = 2.0 * std::numbers::pi * k / n;
    p.emplace_back(a / 2.0 * std::cos(phi) - a / 2.0 + x_front, b / 2.0 * std::sin(phi) + b / 2.0);
  }
  return p;
}

/// create_parallelogram(b, g, theta), counter-clockwise.
inline Polygon thesis_parallelogram(double b, double g, double theta) {
  const double g_long = g / std::sin(theta);
  const double shift = b / std::tan(theta);
  return {{0.0, 0.0}, {g_long, 0.0}, {shift + g_long, b}, {shift, b}};
}

/// Eq. 5.3: twice the area is the sum of the 2x2 determinants of successive vertices.
inline double shoelace_area(const Polygon& p) {
  double twice = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Eigen::Vector2d& u = p[i];
    const Eigen::Vector2d& v = p[(i + 1) % p.size()];
    twice += u.x() * v.y() - v.x() * u.y();
  }
  return 0.5 * std::abs(twice);
}

/// The part of `subject` inside the convex counter-clockwise `clip`: keep what
/// lies on the inner side of each edge line, adding the crossing points.
inline Polygon clip_to_convex(Polygon subject, const Polygon& clip) {
  for (std::size_t e = 0; e < clip.size() && !subject.empty(); ++e) {
    const Eigen::Vector2d a = clip[e];
    const Eigen::Vector2d b = clip[(e + 1) % clip.size()];
    const auto side = [&](const Eigen::Vector2d& p) { return (b.x() - a.x()) * (p.y() - a.y()) - (b.y() - a.y()) * (p.x() - a.x()); };
    Polygon out;
    for (std::size_t i = 0; i < subject.size(); ++i) {
      const Eigen::Vector2d& p = subject[i];
      const Eigen::Vector2d& q = subject[(i + 1) % subject.size()];
      const double sp = side(p);
      const double sq = side(q);
      if (sp >= 0.0) out.push_back(p);
      if ((sp >= 0.0) != (sq >= 0.0)) out.push_back(p + (q - p) * (sp / (sp - sq)));
    }
    subject = std::move(out);
  }
  return subject;
}

/// numpy.gradient(ys, dx).
inline std::vector<double> numpy_gradient(const std::vector<double>& ys, double dx) {
  const std::size_t n = ys.size();
  std::vector<double> d(n);
  d[0] = (ys[1] - ys[0]) / dx;
  d[n - 1] = (ys[n - 1] - ys[n - 2]) / dx;
  for (std::size_t i = 1; i + 1 < n; ++i) d[i] = (ys[i + 1] - ys[i - 1]) / (2.0 * dx);
  return d;
}

}  // namespace railjoint::thesis_reference
