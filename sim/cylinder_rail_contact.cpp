#include "sim/cylinder_rail_contact.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace railjoint {

namespace {

// The axle-nearest point of the edge p0 -> p1 within the wheel's lateral span.
CylinderContact edge_contact(const WheelCylinder& wheel, const Eigen::Vector3d& p0, const Eigen::Vector3d& p1) {
  CylinderContact out;
  const Eigen::Vector3d e = p1 - p0;
  const double y_lo = wheel.centre_m.y() - wheel.half_width_m;
  const double y_hi = wheel.centre_m.y() + wheel.half_width_m;
  // Parameter range of the edge inside the span.
  double lo = 0.0, hi = 1.0;
  if (std::abs(e.y()) > 0.0) {
    const double l0 = (y_lo - p0.y()) / e.y();
    const double l1 = (y_hi - p0.y()) / e.y();
    lo = std::max(lo, std::min(l0, l1));
    hi = std::min(hi, std::max(l0, l1));
    if (lo > hi) return out;
  } else if (p0.y() < y_lo || p0.y() > y_hi) {
    return out;
  }
  // rho^2(l) = |w + l d|^2 in the x-z plane: smallest at l = -w.d / d.d.
  const Eigen::Vector2d d(e.x(), e.z());
  const Eigen::Vector2d w(p0.x() - wheel.centre_m.x(), p0.z() - wheel.centre_m.z());
  const double dd = d.squaredNorm();
  // An edge along y has every point as near: take the one in the wheel's
  // mid-plane (a zero-length edge: its one point).
  const double nearest = dd > 0.0         ? -w.dot(d) / dd
                         : e.y() != 0.0   ? (wheel.centre_m.y() - p0.y()) / e.y()
                                          : 0.0;
  const double l = std::clamp(nearest, lo, hi);
  const Eigen::Vector3d p = p0 + l * e;
  const Eigen::Vector2d radial(wheel.centre_m.x() - p.x(), wheel.centre_m.z() - p.z());
  const double rho = radial.norm();
  if (!(rho > 0.0)) return out;  // the edge runs through the axle: no direction to push
  out.found = true;
  out.distance_m = rho - wheel.radius_m;
  out.point_on_rail_m = p;
  out.normal = Eigen::Vector3d(radial.x() / rho, 0.0, radial.y() / rho);
  return out;
}

// The foot of the axle on the triangle's plane, if the plane contains the y
// direction, faces the wheel, and the triangle holds the foot within the span.
CylinderContact face_contact(const WheelCylinder& wheel, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                             const Eigen::Vector3d& c) {
  CylinderContact out;
  Eigen::Vector3d n = (b - a).cross(c - a);
  const double length = n.norm();
  if (!(length > 0.0)) return out;
  n /= length;
  if (std::abs(n.y()) > 1e-12) return out;
  n.y() = 0.0;
  n.normalize();
  const double s = n.dot(wheel.centre_m - a);
  if (!(s > 0.0)) return out;
  // In the plane, coordinates (u, y) with u along n x y: the triangle is a 2-D
  // triangle; the foot is the line u = u_foot. Its y-interval in the triangle:
  const Eigen::Vector3d u_dir = n.cross(Eigen::Vector3d::UnitY());
  const double u_foot = u_dir.dot(wheel.centre_m);
  const std::array<Eigen::Vector3d, 3> v = {a, b, c};
  double y_min = std::numeric_limits<double>::infinity();
  double y_max = -std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector3d& p = v[static_cast<std::size_t>(i)];
    const Eigen::Vector3d& q = v[static_cast<std::size_t>((i + 1) % 3)];
    const double up = u_dir.dot(p), uq = u_dir.dot(q);
    if ((up - u_foot) * (uq - u_foot) > 0.0) continue;  // the edge does not cross the foot line
    if (up == uq) {
      // Edge on the foot line: both ends count.
      y_min = std::min({y_min, p.y(), q.y()});
      y_max = std::max({y_max, p.y(), q.y()});
      continue;
    }
    const double y = p.y() + (u_foot - up) / (uq - up) * (q.y() - p.y());
    y_min = std::min(y_min, y);
    y_max = std::max(y_max, y);
  }
  const double y_lo = std::max(y_min, wheel.centre_m.y() - wheel.half_width_m);
  const double y_hi = std::min(y_max, wheel.centre_m.y() + wheel.half_width_m);
  if (!(y_lo <= y_hi)) return out;
  out.found = true;
  out.distance_m = s - wheel.radius_m;
  out.normal = n;
  out.point_on_rail_m = wheel.centre_m - s * n;
  out.point_on_rail_m.y() = std::clamp(wheel.centre_m.y(), y_lo, y_hi);
  return out;
}

void keep_nearest(CylinderContact& best, const CylinderContact& candidate) {
  if (candidate.found && candidate.distance_m < best.distance_m) best = candidate;
}

}  // namespace

CylinderContact cylinder_triangle_contact(const WheelCylinder& wheel, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                          const Eigen::Vector3d& c) {
  CylinderContact best = face_contact(wheel, a, b, c);
  keep_nearest(best, edge_contact(wheel, a, b));
  keep_nearest(best, edge_contact(wheel, b, c));
  keep_nearest(best, edge_contact(wheel, c, a));
  return best;
}

CylinderContact cylinder_rail_contact(const WheelCylinder& wheel, const TriangleMesh& rail, double max_distance_m) {
  CylinderContact best;
  for (const Eigen::Vector3i& t : rail.triangles) {
    keep_nearest(best, cylinder_triangle_contact(wheel, rail.vertices_m[static_cast<std::size_t>(t[0])],
                                                 rail.vertices_m[static_cast<std::size_t>(t[1])],
                                                 rail.vertices_m[static_cast<std::size_t>(t[2])]));
  }
  if (best.found && !(best.distance_m <= max_distance_m)) best = CylinderContact{};
  return best;
}

}  // namespace railjoint
