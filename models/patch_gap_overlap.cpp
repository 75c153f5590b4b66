#include "models/patch_gap_overlap.h"

#include <algorithm>
#include <cmath>

#include <boost/geometry.hpp>
#include <boost/geometry/geometries/linestring.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/polygon.hpp>

namespace railjoint {

namespace {

namespace bg = boost::geometry;
using BoostPoint = bg::model::d2::point_xy<double>;
using BoostPolygon = bg::model::polygon<BoostPoint, /*ClockWise=*/false, /*Closed=*/true>;
using BoostLine = bg::model::linestring<BoostPoint>;

double cross(const Eigen::Vector2d& u, const Eigen::Vector2d& v) { return u.x() * v.y() - u.y() * v.x(); }

// Signed area of the sector of the unit disc between the rays to u and v.
double sector_area(const Eigen::Vector2d& u, const Eigen::Vector2d& v) { return 0.5 * std::atan2(cross(u, v), u.dot(v)); }

// The part [t_in, t_out] of the segment p + t (q - p), t in [0, 1], inside the
// unit disc (t_in >= t_out: none).
struct Chord {
  double t_in = 1.0;
  double t_out = 0.0;
  bool empty() const { return !(t_in < t_out); }
};

Chord chord_in_unit_disc(const Eigen::Vector2d& p, const Eigen::Vector2d& q) {
  const Eigen::Vector2d d = q - p;
  const double A = d.squaredNorm();
  const double B = p.dot(d);  // half the linear coefficient
  const double C = p.squaredNorm() - 1.0;
  const double discriminant = B * B - A * C;
  if (A == 0.0 || discriminant <= 0.0) return {};
  const double root = std::sqrt(discriminant);
  // Both roots without cancellation: t1 t2 = C / A.
  const double far = (B >= 0.0) ? (-B - root) / A : (-B + root) / A;
  const double near = (far != 0.0) ? C / (A * far) : 0.0;
  const double t1 = std::min(far, near);
  const double t2 = std::max(far, near);
  return {std::clamp(t1, 0.0, 1.0), std::clamp(t2, 0.0, 1.0)};
}

// Signed area of the unit disc inside the triangle (0, p, q).
double disc_in_triangle(const Eigen::Vector2d& p, const Eigen::Vector2d& q) {
  const Chord chord = chord_in_unit_disc(p, q);
  if (chord.empty()) return sector_area(p, q);
  const Eigen::Vector2d in = p + chord.t_in * (q - p);
  const Eigen::Vector2d out = p + chord.t_out * (q - p);
  return sector_area(p, in) + 0.5 * cross(in, out) + sector_area(out, q);
}

std::vector<Eigen::Vector2d> gap_polygon(const EndPostGap& gap, double width_m) {
  const auto corners = gap_parallelogram_m(gap, width_m);
  return {corners.begin(), corners.end()};
}

BoostPolygon to_boost(const std::vector<Eigen::Vector2d>& polygon) {
  BoostPolygon out;
  for (const Eigen::Vector2d& p : polygon) bg::append(out.outer(), BoostPoint(p.x(), p.y()));
  bg::append(out.outer(), BoostPoint(polygon.front().x(), polygon.front().y()));
  return out;
}

GapOverlap ellipse_overlap(const ContactPatch& patch, const EndPostGap& gap, double x_front_m) {
  const Eigen::Vector2d centre = patch_centre_m(patch, x_front_m);
  const Eigen::Vector2d semi_axes(patch.length_m / 2.0, patch.width_m / 2.0);
  std::vector<Eigen::Vector2d> unit = gap_polygon(gap, patch.width_m);
  for (Eigen::Vector2d& p : unit) p = (p - centre).cwiseQuotient(semi_axes);

  GapOverlap overlap;
  double boundary_dy = 0.0;  // sum of (fraction of the edge inside) * Delta y, in metres
  for (std::size_t i = 0; i < unit.size(); ++i) {
    const Eigen::Vector2d& p = unit[i];
    const Eigen::Vector2d& q = unit[(i + 1) % unit.size()];
    overlap.area_m2 += disc_in_triangle(p, q);
    const Chord chord = chord_in_unit_disc(p, q);
    if (!chord.empty()) boundary_dy += (chord.t_out - chord.t_in) * (q.y() - p.y()) * semi_axes.y();
  }
  overlap.area_m2 *= semi_axes.x() * semi_axes.y();
  overlap.d_area_d_x_front_m = -boundary_dy;
  return overlap;
}

GapOverlap polygon_overlap(const ContactPatch& patch, const EndPostGap& gap, double x_front_m) {
  const std::vector<Eigen::Vector2d> gap_corners = gap_polygon(gap, patch.width_m);
  const BoostPolygon outline = to_boost(patch_polygon_m(patch, x_front_m));
  GapOverlap overlap;
  std::vector<BoostPolygon> pieces;
  bg::intersection(outline, to_boost(gap_corners), pieces);
  for (const BoostPolygon& piece : pieces) overlap.area_m2 += bg::area(piece);

  double boundary_dy = 0.0;
  for (std::size_t i = 0; i < gap_corners.size(); ++i) {
    const Eigen::Vector2d& p = gap_corners[i];
    const Eigen::Vector2d& q = gap_corners[(i + 1) % gap_corners.size()];
    if (q.y() == p.y()) continue;  // an edge along x sweeps nothing
    BoostLine edge;
    bg::append(edge, BoostPoint(p.x(), p.y()));
    bg::append(edge, BoostPoint(q.x(), q.y()));
    std::vector<BoostLine> inside;
    bg::intersection(edge, outline, inside);
    double length_inside = 0.0;
    for (const BoostLine& piece : inside) length_inside += bg::length(piece);
    boundary_dy += length_inside / (q - p).norm() * (q.y() - p.y());
  }
  overlap.d_area_d_x_front_m = -boundary_dy;
  return overlap;
}

}  // namespace

GapOverlap patch_gap_overlap(const ContactPatch& patch, const EndPostGap& gap, double x_front_m) {
  return patch.shape == PatchShape::ellipse ? ellipse_overlap(patch, gap, x_front_m)
                                            : polygon_overlap(patch, gap, x_front_m);
}

double unit_disc_polygon_area(const std::vector<Eigen::Vector2d>& polygon) {
  double area = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) area += disc_in_triangle(polygon[i], polygon[(i + 1) % polygon.size()]);
  return area;
}

double polygon_intersection_area_m2(const std::vector<Eigen::Vector2d>& a, const std::vector<Eigen::Vector2d>& b) {
  std::vector<BoostPolygon> pieces;
  bg::intersection(to_boost(a), to_boost(b), pieces);
  double area = 0.0;
  for (const BoostPolygon& piece : pieces) area += bg::area(piece);
  return area;
}

std::vector<std::vector<Eigen::Vector2d>> outline_over_gap_m(const std::vector<Eigen::Vector2d>& outline,
                                                             const EndPostGap& gap, double width_m) {
  std::vector<BoostPolygon> pieces;
  bg::intersection(to_boost(outline), to_boost(gap_polygon(gap, width_m)), pieces);
  std::vector<std::vector<Eigen::Vector2d>> out;
  for (const BoostPolygon& piece : pieces) {
    std::vector<Eigen::Vector2d> points;
    const auto& ring = piece.outer();
    for (std::size_t i = 0; i + 1 < ring.size(); ++i) points.emplace_back(ring[i].x(), ring[i].y());
    out.push_back(std::move(points));
  }
  return out;
}

}  // namespace railjoint
