#pragma once
// Draws a recorded wheel crossing the rail joint, one frame per call: the two
// rail solids (top, cut and side faces in different colours), the wheel (rim
// ticks, a dark bar and a knob so its spin shows), the path of the wheel's
// lowest point so far, the contact points of the nearest recorded sample, the
// impacts (a big ring, an orange border and a label on frames within one
// frame period of an impact, a small dot afterwards), a ground checker, a
// datum line at the reference height behind everything, scale bars and labels.
//
// Everything, the wheel included, is drawn through the one affine map of
// VerticalExaggeration, so the drawn wheel (an ellipse k times taller than
// wide in the side view) touches the drawn rails exactly where the real
// wheel touches the real rails and overlaps them only where it really does.
// The side view is a section through the wheel's width at the lateral
// position of the first sample (the carrier holds y; renders/slab_section.h);
// the top and perspective views show the whole rails. Every view is centred
// on the wheel's drawn lowest point, where it meets the rails (renders/camera.h).

#include <memory>
#include <string>

#include "geometry/rail_joint_mesh.h"
#include "geometry/triangle_mesh.h"
#include "renders/camera.h"
#include "renders/frame_schedule.h"
#include "renders/offscreen_renderer.h"
#include "renders/render_settings.h"
#include "renders/rgb_image.h"
#include "renders/vertical_exaggeration.h"
#include "sim/trajectory.h"

namespace railjoint {

class CrossingRenderer {
 public:
  /// Checks the settings and the window against the trajectory (InputError),
  /// the meshes (std::invalid_argument; the rails must be convex solids for
  /// the side view's section), then creates the GL context (std::runtime_error
  /// without OSMesa). The wheel mesh is centred at the origin with its axle
  /// along y; its radius and half-width are read from it. Use a fine one
  /// (renders/wheel_tessellation.h): a coarse polygon shows its facets,
  /// k times magnified, in the contact view. The trajectory is copied.
  CrossingRenderer(const RenderSettings& settings, const RailJointMesh& rails, const TriangleMesh& wheel,
                   const Trajectory& trajectory);
  ~CrossingRenderer();

  const FrameWindow& window() const { return window_; }
  const std::string& gl_version() const;
  const std::string& gl_renderer() const;

  /// Frame k of the window (0 <= k < window().count).
  void render_frame(long long k, RgbImage& out);
  /// Any instant (clamped to the trajectory's ends).
  void render_at(double t_s, RgbImage& out);

  /// The drawn point the view at t_s is centred on: the wheel's drawn lowest
  /// point (following), or the middle of its range over the window (fixed camera).
  Eigen::Vector3d focus_at(double t_s) const;
  /// The camera used for a frame at t_s.
  Camera camera_at(double t_s) const;

 private:
  FrameDrawList frame_at(double t_s) const;

  RenderSettings settings_;
  Trajectory trajectory_;
  FrameWindow window_;
  VerticalExaggeration exaggeration_;
  CameraFraming framing_;
  double wheel_radius_m_ = 0.0;
  double wheel_half_width_m_ = 0.0;
  double px_per_m_ = 1.0;  ///< image pixels per drawn metre at the focus
  Eigen::Vector3d fixed_focus_m_ = Eigen::Vector3d::Zero();
  std::unique_ptr<OffscreenRenderer> gl_;
  MeshHandle rails_ = -1, ground_ = -1, datum_ = -1, wheel_ = -1, path_ = -1;
};

}  // namespace railjoint
