#include "renders/side_view_framing.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "renders/crossing_meshes.h"

namespace railjoint {


SideViewFraming::SideViewFraming(const std::vector<const TriangleMesh*>& rails, double wheel_y_m, double wheel_radius_m,
                                 const VerticalExaggeration& exaggeration)
    : wheel_y_m_(wheel_y_m), wheel_radius_m_(wheel_radius_m), exaggeration_(exaggeration) {
  for (const TriangleMesh* mesh : rails) {
    for (std::size_t i = 0; i < mesh->triangles.size(); ++i) {
      if (mesh->tags[i] != FaceTag::top) continue;
      Eigen::Matrix3d corners;
      for (int c = 0; c < 3; ++c) corners.col(c) = mesh->vertices_m[static_cast<std::size_t>(mesh->triangles[i][c])];
      tops_.push_back(corners);
    }
  }
}

std::pair<double, const Eigen::Matrix3d*> SideViewFraming::top_face_below(double x_m) const {
  double top = std::numeric_limits<double>::quiet_NaN();
  const Eigen::Matrix3d* face = nullptr;
  for (const Eigen::Matrix3d& t : tops_) {
    // Barycentric coordinates of (x, y) in the triangle's plan view.
    const Eigen::Vector2d a = t.col(0).head<2>(), b = t.col(1).head<2>(), c = t.col(2).head<2>();
    const Eigen::Vector2d p(x_m, wheel_y_m_);
    const double area = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
    if (std::abs(area) < 1e-18) continue;  // a face seen edge on
    const double u = ((b - p).x() * (c - p).y() - (b - p).y() * (c - p).x()) / area;
    const double v = ((c - p).x() * (a - p).y() - (c - p).y() * (a - p).x()) / area;
    const double w = 1.0 - u - v;
    constexpr double kOnEdge = -1e-12;
    if (u < kOnEdge || v < kOnEdge || w < kOnEdge) continue;
    const double z = u * t(2, 0) + v * t(2, 1) + w * t(2, 2);
    if (face == nullptr || z > top) {
      top = z;
      face = &t;
    }
  }
  return {top, face};
}

double SideViewFraming::clearance_above(const Eigen::Matrix3d& face, const Eigen::Vector3d& centre_m) const {
  Eigen::Vector3d normal = (face.col(1) - face.col(0)).cross(face.col(2) - face.col(0)).normalized();
  if (normal.z() < 0.0) normal = -normal;
  return normal.dot(centre_m - face.col(0)) - wheel_radius_m_;
}

double SideViewFraming::clearance_m(const Eigen::Vector3d& centre_m) const {
  const Eigen::Matrix3d* face = top_face_below(centre_m.x()).second;
  return face == nullptr ? std::numeric_limits<double>::quiet_NaN() : clearance_above(*face, centre_m);
}

std::optional<double> SideViewFraming::drawn_top_under_flight(const Eigen::Vector3d& centre_m) const {
  const auto [top_m, face] = top_face_below(centre_m.x());
  if (face == nullptr || !(clearance_above(*face, centre_m) > kTouchingGap_m)) return std::nullopt;
  return exaggeration_.point(Eigen::Vector3d(centre_m.x(), wheel_y_m_, top_m)).z();
}

Eigen::Vector3d SideViewFraming::focus(const Eigen::Vector3d& centre_m) const {
  const Eigen::Vector3d lowest = exaggeration_.lowest_wheel_point(centre_m, wheel_radius_m_);
  const std::optional<double> drawn_top = drawn_top_under_flight(centre_m);
  if (!drawn_top) return lowest;  // on a rail, or off the rails
  return Eigen::Vector3d(lowest.x(), lowest.y(), 0.5 * (lowest.z() + *drawn_top));
}

double SideViewFraming::width_for_flights(const Trajectory& trajectory, const FrameWindow& window, double width_m,
                                          double aspect) const {
  double largest_gap = 0.0;  // drawn [m]
  for (const WheelSample& s : trajectory.samples) {
    if (s.time_s < window.t_start_s || s.time_s > window.t_end_s) continue;
    const std::optional<double> drawn_top = drawn_top_under_flight(s.centre_m);
    if (!drawn_top) continue;
    largest_gap = std::max(largest_gap, exaggeration_.lowest_wheel_point(s.centre_m, wheel_radius_m_).z() - *drawn_top);
  }
  return std::max(width_m, largest_gap / kGapShareOfHeight * aspect);
}

}  // namespace railjoint
