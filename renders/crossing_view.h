#pragma once
// One picture of a recorded crossing: the side, top or perspective view
// (renders/side_view.h, top_view.h, perspective_view.h). A view owns its
// meshes, its layout and its labels; what all three share lives in the
// CrossingSetup it is given (renders/crossing_setup.h), which outlives it.

#include <Eigen/Core>

#include "renders/camera.h"
#include "renders/crossing_setup.h"
#include "renders/offscreen_renderer.h"

namespace railjoint {

class CrossingView {
 public:
  explicit CrossingView(CrossingSetup& setup) : setup_(setup) {}
  virtual ~CrossingView() = default;
  CrossingView(const CrossingView&) = delete;
  CrossingView& operator=(const CrossingView&) = delete;

  /// The drawn point the close view at t_s is centred on: the wheel's drawn
  /// lowest point (following), or the middle of its range over the window
  /// (fixed camera).
  virtual Eigen::Vector3d focus_at(double t_s) const {
    if (!setup_.settings.follow_wheel) return setup_.fixed_focus_m;
    return setup_.exaggeration.lowest_wheel_point(sample_at(setup_.trajectory, t_s).centre_m, setup_.wheel_radius_m);
  }
  /// The camera of the close view at t_s (side, top, or the perspective inset).
  virtual Camera camera_at(double t_s) const { return make_camera(setup_.settings, setup_.framing, focus_at(t_s)); }
  /// (t_s) => the meshes that change from frame to frame (the top view's running band).
  virtual void update_meshes(double /*t_s*/) {}
  /// (t_s) => the scenes and the overlay (labels, borders, scale bars, legend) of the frame.
  virtual FrameDrawList frame_at(double t_s) const = 0;

 protected:
  /// The scene of a close view (side, top) seen by `camera`, its key light
  /// from the viewer's side of the track, above and a little behind.
  static SceneDraw close_scene(const Camera& camera) {
    return scene_seen_by(camera, Eigen::Vector3f(-0.35f, -0.8f, 0.5f).normalized());
  }

  CrossingSetup& setup_;
};

}  // namespace railjoint
