#include "renders/camera.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace railjoint {

namespace {

Eigen::Matrix4d look_at(const Eigen::Vector3d& eye, const Eigen::Vector3d& target, const Eigen::Vector3d& up) {
  const Eigen::Vector3d f = (target - eye).normalized();
  const Eigen::Vector3d s = f.cross(up).normalized();
  const Eigen::Vector3d u = s.cross(f);
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.block<1, 3>(0, 0) = s.transpose();
  m.block<1, 3>(1, 0) = u.transpose();
  m.block<1, 3>(2, 0) = -f.transpose();
  m(0, 3) = -s.dot(eye);
  m(1, 3) = -u.dot(eye);
  m(2, 3) = f.dot(eye);
  return m;
}

Eigen::Matrix4d orthographic(double half_w, double half_h, double near, double far) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m(0, 0) = 1.0 / half_w;
  m(1, 1) = 1.0 / half_h;
  m(2, 2) = -2.0 / (far - near);
  m(2, 3) = -(far + near) / (far - near);
  return m;
}

Eigen::Matrix4d perspective(double fovy_rad, double aspect, double near, double far) {
  const double f = 1.0 / std::tan(fovy_rad / 2.0);
  Eigen::Matrix4d m = Eigen::Matrix4d::Zero();
  m(0, 0) = f / aspect;
  m(1, 1) = f;
  m(2, 2) = (far + near) / (near - far);
  m(2, 3) = 2.0 * far * near / (near - far);
  m(3, 2) = -1.0;
  return m;
}

// Depth range along the view direction that holds the whole scene.
void depth_range(const Eigen::Matrix4d& view, const Eigen::AlignedBox3d& box, double& near, double& far) {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -lo;
  for (int corner = 0; corner < 8; ++corner) {
    const Eigen::Vector3d p = box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(corner));
    const double depth = -(view * p.homogeneous()).z();
    lo = std::min(lo, depth);
    hi = std::max(hi, depth);
  }
  const double margin = 0.05 * (hi - lo) + 1e-3;
  near = lo - margin;
  far = hi + margin;
}

}  // namespace

double visible_width_m(const RenderSettings& settings, const CameraFraming& framing) {
  if (settings.view_width_m) return *settings.view_width_m;
  if (settings.view == RenderView::top) {
    const double aspect = static_cast<double>(settings.width_px) / static_cast<double>(settings.height_px);
    return 3.0 * framing.rail_width_m * aspect;
  }
  return kDefaultContactViewWidth_m;
}

Camera make_camera(const RenderSettings& settings, const CameraFraming& framing, const Eigen::Vector3d& focus_m) {
  const double aspect = static_cast<double>(settings.width_px) / static_cast<double>(settings.height_px);
  Camera camera;
  camera.visible_width_m = visible_width_m(settings, framing);
  camera.visible_height_m = camera.visible_width_m / aspect;
  Eigen::AlignedBox3d bounds = framing.scene_bounds;
  if (bounds.isEmpty()) bounds = Eigen::AlignedBox3d(Eigen::Vector3d(-1, -1, -1), Eigen::Vector3d(1, 1, 1));
  bounds.extend(focus_m);
  // side: looking along +y, z up; top: looking down, y up.
  const bool side = settings.view == RenderView::side;
  const Eigen::Vector3d direction = side ? Eigen::Vector3d::UnitY() : Eigen::Vector3d(-Eigen::Vector3d::UnitZ());
  const Eigen::Vector3d up = side ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d centre(focus_m.x(), 0.0, focus_m.z());
  // Stand outside the scene; an orthographic camera only needs the direction.
  const double reach = (bounds.max() - bounds.min()).norm() + 1.0;
  const Eigen::Vector3d along = direction.dot(centre) * direction;
  Eigen::Vector3d eye = centre - along;  // centre projected onto the plane through the origin
  const double behind = std::min(direction.dot(bounds.min()), direction.dot(bounds.max()));
  eye += (behind - reach) * direction;
  camera.eye_m = eye;
  camera.to_viewer = -direction;
  camera.view = look_at(eye, eye + direction, up);
  double near = 0.0, far = 0.0;
  depth_range(camera.view, bounds, near, far);
  camera.projection = orthographic(camera.visible_width_m / 2.0, camera.visible_height_m / 2.0, near, far);
  return camera;
}

Camera look_at_focus(const Eigen::Vector3d& focus_m, const Eigen::Vector3d& to_eye, double fovy_rad, double aspect,
                     double visible_width_m, const Eigen::AlignedBox3d& bounds_in) {
  Camera camera;
  camera.orthographic = false;
  camera.visible_width_m = visible_width_m;
  camera.visible_height_m = visible_width_m / aspect;
  const double distance = 0.5 * camera.visible_height_m / std::tan(fovy_rad / 2.0);
  camera.to_viewer = to_eye.normalized();
  camera.eye_m = focus_m + distance * camera.to_viewer;
  camera.view = look_at(camera.eye_m, focus_m, Eigen::Vector3d::UnitZ());
  Eigen::AlignedBox3d bounds = bounds_in;
  bounds.extend(focus_m);
  double near = 0.0, far = 0.0;
  depth_range(camera.view, bounds, near, far);
  // Nothing drawn comes closer to the eye than a few percent of the focus
  // distance (the eye stands beside the rails, in front of the wheel face).
  near = std::max(near, 0.02 * distance);
  far = std::max(far, 2.0 * distance);
  camera.projection = perspective(fovy_rad, aspect, near, far);
  return camera;
}

Camera fit_perspective_camera(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& to_eye, double fovy_rad,
                              double aspect, double margin, const Eigen::AlignedBox3d& bounds_in) {
  const Eigen::Vector3d f = -to_eye.normalized();  // looking along f
  const Eigen::Vector3d s = f.cross(Eigen::Vector3d::UnitZ()).normalized();
  const Eigen::Vector3d u = s.cross(f);
  const double ty = std::tan(fovy_rad / 2.0) * (1.0 - margin);
  const double tx = std::tan(fovy_rad / 2.0) * aspect * (1.0 - margin);
  // Per axis a with slope t: the eye's along-view coordinate e_d must satisfy
  // e_d <= (min(a_i + t d_i) - max(a_i - t d_i)) / (2 t); then e_a is the middle
  // of [max(a_i - t (d_i - e_d)), min(a_i + t (d_i - e_d))].
  double lo_s = std::numeric_limits<double>::infinity(), hi_s = -lo_s, lo_u = lo_s, hi_u = -lo_s;
  for (const auto& p : points) {
    const double d = f.dot(p), a = s.dot(p), b = u.dot(p);
    lo_s = std::min(lo_s, a + tx * d);  // min(a + t d)
    hi_s = std::max(hi_s, a - tx * d);  // max(a - t d)
    lo_u = std::min(lo_u, b + ty * d);
    hi_u = std::max(hi_u, b - ty * d);
  }
  const double e_d = std::min((lo_s - hi_s) / (2.0 * tx), (lo_u - hi_u) / (2.0 * ty));
  const double e_s = 0.5 * ((hi_s + tx * e_d) + (lo_s - tx * e_d));
  const double e_u = 0.5 * ((hi_u + ty * e_d) + (lo_u - ty * e_d));
  Camera camera;
  camera.orthographic = false;
  camera.eye_m = e_s * s + e_u * u + e_d * f;
  camera.to_viewer = -f;
  camera.view = look_at(camera.eye_m, camera.eye_m + f, Eigen::Vector3d::UnitZ());
  Eigen::AlignedBox3d bounds = bounds_in;
  double near = std::numeric_limits<double>::infinity(), far = 0.0;
  for (const auto& p : points) {
    near = std::min(near, f.dot(p) - e_d);
    far = std::max(far, f.dot(p) - e_d);
  }
  if (!bounds.isEmpty()) {
    double box_near = 0.0, box_far = 0.0;
    depth_range(camera.view, bounds, box_near, box_far);
    far = std::max(far, box_far);
  }
  // The scene may reach closer than the framed points (the ground under the
  // camera); a near plane at a tenth of the nearest framed point keeps depth precision.
  near = std::max(0.1 * near, 1e-3);
  camera.projection = perspective(fovy_rad, aspect, near, far * 1.05);
  const double focus_distance = 0.5 * (near * 10.0 + far);
  camera.visible_height_m = 2.0 * std::tan(fovy_rad / 2.0) * focus_distance;
  camera.visible_width_m = camera.visible_height_m * aspect;
  return camera;
}

}  // namespace railjoint
