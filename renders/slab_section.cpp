#include "renders/slab_section.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Geometry>

namespace railjoint {

namespace {

using Polygon = std::vector<Eigen::Vector3d>;

// Where the edge a-b crosses y = plane_y. Computed from the endpoints in a
// fixed order, so the two triangles sharing an edge get the same point bit for bit.
Eigen::Vector3d crossing(Eigen::Vector3d a, Eigen::Vector3d b, double plane_y) {
  if (std::lexicographical_compare(b.data(), b.data() + 3, a.data(), a.data() + 3)) std::swap(a, b);
  const double w = (plane_y - a.y()) / (b.y() - a.y());
  Eigen::Vector3d p = a + w * (b - a);
  p.y() = plane_y;  // exactly on the plane
  return p;
}

// Sutherland-Hodgman against one half-space: keep side * (y - plane_y) >= 0.
// Points on the plane are appended to `on_plane`; `removed` is set when a
// vertex lies on the far side.
Polygon clip(const Polygon& polygon, double plane_y, double side, std::vector<Eigen::Vector3d>& on_plane,
             bool& removed) {
  Polygon out;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d& a = polygon[i];
    const Eigen::Vector3d& b = polygon[(i + 1) % n];
    const double da = side * (a.y() - plane_y);
    const double db = side * (b.y() - plane_y);
    if (da >= 0.0) {
      out.push_back(a);
      if (da == 0.0) on_plane.push_back(a);
    } else {
      removed = true;
    }
    if ((da > 0.0 && db < 0.0) || (da < 0.0 && db > 0.0)) {
      out.push_back(crossing(a, b, plane_y));
      on_plane.push_back(out.back());
    }
  }
  return out;
}

double cross2(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

// Convex hull (Andrew's monotone chain) of points in the (x, z) plane,
// counter-clockwise, collinear points dropped.
std::vector<Eigen::Vector2d> convex_hull(std::vector<Eigen::Vector2d> points) {
  std::sort(points.begin(), points.end(),
            [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); });
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (points.size() < 3) return {};
  std::vector<Eigen::Vector2d> hull(2 * points.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    while (k >= 2 && cross2(hull[k - 2], hull[k - 1], points[i]) <= 0.0) --k;
    hull[k++] = points[i];
  }
  for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross2(hull[k - 2], hull[k - 1], points[i]) <= 0.0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);
  return hull;
}

struct Face {
  Polygon polygon;
  FaceTag tag;
};

// Clips every face against one half-space and closes the solid with the section face.
std::vector<Face> cut(const std::vector<Face>& faces, double plane_y, double side) {
  std::vector<Face> out;
  std::vector<Eigen::Vector3d> on_plane;
  bool removed = false;
  for (const Face& f : faces) {
    Polygon p = clip(f.polygon, plane_y, side, on_plane, removed);
    if (p.size() >= 3) out.push_back({std::move(p), f.tag});
  }
  // Nothing cut off (e.g. the plane touches a face of the solid): no new face.
  if (!removed) return out;
  std::vector<Eigen::Vector2d> xz;
  xz.reserve(on_plane.size());
  for (const auto& p : on_plane) xz.emplace_back(p.x(), p.z());
  const std::vector<Eigen::Vector2d> hull = convex_hull(std::move(xz));
  if (hull.size() >= 3) {
    // A polygon counter-clockwise in (x, z) has the normal x cross z = -y:
    // outward for the y_min plane (side +1); reversed for the y_max plane.
    Polygon section;
    for (const auto& q : hull) section.emplace_back(q.x(), plane_y, q.y());
    if (side < 0.0) std::reverse(section.begin(), section.end());
    out.push_back({std::move(section), FaceTag::side});
  }
  return out;
}

void check_convex(const TriangleMesh& solid) {
  double size = 0.0;
  for (const auto& v : solid.vertices_m) size = std::max(size, v.cwiseAbs().maxCoeff());
  const double tolerance = 1e-9 * std::max(size, 1e-3);
  for (const Eigen::Vector3i& t : solid.triangles) {
    const Eigen::Vector3d& a = solid.vertices_m[static_cast<std::size_t>(t[0])];
    const Eigen::Vector3d n = (solid.vertices_m[static_cast<std::size_t>(t[1])] - a)
                                  .cross(solid.vertices_m[static_cast<std::size_t>(t[2])] - a);
    if (!(n.norm() > 0.0)) continue;  // a degenerate triangle bounds nothing
    const Eigen::Vector3d unit = n.normalized();
    for (const auto& v : solid.vertices_m) {
      if (unit.dot(v - a) > tolerance) {
        throw std::invalid_argument("render: the side-view section needs convex rail solids; a vertex lies " +
                                    std::to_string(unit.dot(v - a)) + " m outside a face plane");
      }
    }
  }
}

}  // namespace

TriangleMesh cut_convex_solid_to_slab(const TriangleMesh& solid, double y_min_m, double y_max_m) {
  if (!(y_max_m >= y_min_m)) {
    throw std::invalid_argument("render: section slab with y_max < y_min (" + std::to_string(y_max_m) + " < " +
                                std::to_string(y_min_m) + ")");
  }
  check_convex(solid);
  std::vector<Face> faces;
  faces.reserve(solid.triangles.size());
  for (std::size_t i = 0; i < solid.triangles.size(); ++i) {
    const Eigen::Vector3i& t = solid.triangles[i];
    faces.push_back({{solid.vertices_m[static_cast<std::size_t>(t[0])], solid.vertices_m[static_cast<std::size_t>(t[1])],
                      solid.vertices_m[static_cast<std::size_t>(t[2])]},
                     solid.tags[i]});
  }
  faces = cut(faces, y_min_m, +1.0);
  faces = cut(faces, y_max_m, -1.0);

  TriangleMesh out;
  for (const Face& f : faces) {
    // Convex polygons (clipped triangles, sections): fans from the first vertex.
    for (std::size_t i = 1; i + 1 < f.polygon.size(); ++i) {
      const int base = static_cast<int>(out.vertices_m.size());
      out.vertices_m.push_back(f.polygon[0]);
      out.vertices_m.push_back(f.polygon[i]);
      out.vertices_m.push_back(f.polygon[i + 1]);
      out.triangles.emplace_back(base, base + 1, base + 2);
      out.tags.push_back(f.tag);
    }
  }
  return out;
}

}  // namespace railjoint
