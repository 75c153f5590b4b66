#pragma once
// Where the camera stands for each view, as view and projection matrices
// (OpenGL conventions, column vectors) in the drawn (exaggerated) world.
// Every view is centred on a focus point, in drawn coordinates: the crossing
// renderer passes the drawn lowest point of the wheel, where it touches the rails.
//
// Orthographic views map the visible rectangle linearly onto the image, with
// square pixels (visible width W, height H = W * height / width):
//   side:  looking along +y; image x = world x, image up = world z (drawn).
//          W = view_width_m, default kDefaultContactViewWidth_m; the image
//          centre is the focus (x_f, z_f).
//   top:   looking down -z; image x = world x, image up = world y.
//          H = 3 rail widths unless view_width_m is set; centre (x_f, y = 0).
// Pixel coordinates of a world point (u right, v down, from the top-left corner
// of the image, pixel (i, j) covering [i, i+1) x [j, j+1)), s = width / W px/m:
//   side: u = width / 2 + (x - x_f) s,   v = height / 2 - (z' - z_f) s
//   top:  u = width / 2 + (x - x_f) s,   v = height / 2 - y s
// The perspective view places its cameras itself (renders/perspective_view.h).

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <vector>

#include "renders/render_settings.h"

namespace railjoint {

/// What the camera needs to know about the scene.
struct CameraFraming {
  double rail_width_m = 0.04;        ///< lateral extent of the rail heads [m] (top view height)
  Eigen::AlignedBox3d scene_bounds;  ///< everything drawn, for the depth range
};

struct Camera {
  Eigen::Matrix4d view = Eigen::Matrix4d::Identity();
  Eigen::Matrix4d projection = Eigen::Matrix4d::Identity();
  bool orthographic = true;
  Eigen::Vector3d eye_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d to_viewer = Eigen::Vector3d::UnitZ();  ///< unit, towards the viewer
  double visible_width_m = 0.0;   ///< at the focus (perspective) or everywhere (orthographic)
  double visible_height_m = 0.0;
};

/// Visible width W of the view [m] (see above), before a camera is placed.
double visible_width_m(const RenderSettings& settings, const CameraFraming& framing);

/// The side or top view's camera; focus_m: the drawn point the view is centred on.
Camera make_camera(const RenderSettings& settings, const CameraFraming& framing, const Eigen::Vector3d& focus_m);

/// A perspective camera (vertical field of view fovy_rad, image aspect
/// width / height) looking at focus_m from the direction to_eye (towards the
/// viewer), from the distance at which the visible width at the focus is
/// visible_width_m; its depth range holds `bounds` (the whole scene).
Camera look_at_focus(const Eigen::Vector3d& focus_m, const Eigen::Vector3d& to_eye, double fovy_rad, double aspect,
                     double visible_width_m, const Eigen::AlignedBox3d& bounds);

/// A perspective camera looking along -to_eye that holds every one of
/// `points` in the picture with `margin` (a fraction of the half-width and
/// half-height) to spare, as close as it can stand: for each image axis the
/// points' constraint |s_i - e_s| <= tan(half angle) (1 - margin) (d_i - e_d)
/// is linear in the eye's position (e_s across, e_d along the view), so the
/// nearest eye and its centring follow in closed form. The depth range holds `bounds`.
Camera fit_perspective_camera(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& to_eye, double fovy_rad,
                              double aspect, double margin, const Eigen::AlignedBox3d& bounds);

}  // namespace railjoint
