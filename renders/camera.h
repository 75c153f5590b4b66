#pragma once
// Where the camera stands for each view, as view and projection matrices
// (OpenGL conventions, column vectors) in the drawn (exaggerated) world.
//
// Orthographic views map the visible rectangle linearly onto the image:
//   side:  looking along +y; image x = world x, image up = world z.
//          Visible height H = 2.6 R (or view_width_m * height / width when
//          view_width_m is set), width W = H * width / height; the image
//          centre is at (centre_x, z_ref + 0.75 R), so the wheel (centre near
//          z_ref + R) and the rail top (near z_ref) both show.
//   top:   looking down -z; image x = world x, image up = world y.
//          Visible height 3 rail widths (or from view_width_m); centre (centre_x, y = 0).
// Pixel coordinates of a world point (u right, v down, from the top-left corner
// of the image, pixel (i, j) covering [i, i+1) x [j, j+1)):
//   u = width / 2 + (x - centre_x) * width / W,  v = height / 2 - (up - centre_up) * height / H.
// Perspective: 45 degree vertical field of view from (-1.5 R, -3.0 R, +1.2 R)
// relative to (centre_x, y_wheel, z_ref + 0.75 R), looking at that point, so
// the whole wheel and the joint below it show.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "renders/render_settings.h"

namespace railjoint {

/// What the camera needs to know about the scene.
struct CameraFraming {
  double wheel_radius_m = 0.475;
  double rail_width_m = 0.04;        ///< lateral extent of the rail heads [m]
  double reference_z_m = 0.0;
  double wheel_lateral_m = 0.0;      ///< y of the wheel (perspective target) [m]
  Eigen::AlignedBox3d scene_bounds;  ///< everything drawn, for the depth range
};

struct Camera {
  Eigen::Matrix4d view = Eigen::Matrix4d::Identity();
  Eigen::Matrix4d projection = Eigen::Matrix4d::Identity();
  bool orthographic = true;
  Eigen::Vector3d eye_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d to_viewer = Eigen::Vector3d::UnitZ();  ///< unit, towards the viewer
  double visible_width_m = 0.0;   ///< orthographic views only
  double visible_height_m = 0.0;  ///< orthographic views only
};

/// centre_x_m: the world x the image is centred on (the wheel's x when following).
Camera make_camera(const RenderSettings& settings, const CameraFraming& framing, double centre_x_m);

}  // namespace railjoint
