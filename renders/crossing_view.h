#pragma once
// A recorded wheel crossing the rail joint, drawn one frame per call in one
// of three views, each its own class: the side view (renders/side_view.h),
// the top view (renders/top_view.h) and the perspective view
// (renders/perspective_view.h). A view owns its meshes, its layout and its
// labels; what all three share, the checked input, the exaggeration map, the
// GL context and the common meshes, is its CrossingSetup
// (renders/crossing_setup.h).

#include <memory>
#include <string>

#include <Eigen/Core>

#include "geometry/rail_joint_mesh.h"
#include "geometry/triangle_mesh.h"
#include "renders/camera.h"
#include "renders/crossing_setup.h"
#include "renders/offscreen_renderer.h"
#include "renders/render_settings.h"
#include "renders/rgb_image.h"
#include "sim/trajectory.h"

namespace railjoint {

class CrossingView {
 public:
  /// The view settings.view asks for. Checks the settings and the window
  /// against the trajectory (InputError), the meshes (std::invalid_argument;
  /// the rails must be convex solids for the side view's section), then
  /// creates the GL context (std::runtime_error when it is not built or
  /// refuses). The wheel mesh is centred at the origin with its axle along y;
  /// its radius and half-width are read from it. Use a fine one
  /// (renders/wheel_tessellation.h): a coarse polygon shows its facets, k
  /// times magnified, in the contact view. The trajectory is copied.
  static std::unique_ptr<CrossingView> make(const RenderSettings& settings, const RailJointMesh& rails,
                                            const TriangleMesh& wheel, const Trajectory& trajectory);
  virtual ~CrossingView() = default;
  CrossingView(const CrossingView&) = delete;
  CrossingView& operator=(const CrossingView&) = delete;

  const FrameWindow& window() const { return setup_.window; }
  const std::string& gl_version() const { return setup_.gl->gl_version(); }
  const std::string& gl_renderer() const { return setup_.gl->gl_renderer(); }

  /// The frame at t_s (clamped to the trajectory's ends): render_at finishes
  /// it, draw_at leaves that to finish_frame (renders/read_back_frame.h).
  void render_at(double t_s, RgbImage& out);
  void draw_at(double t_s, ReadBackFrame& out);

  /// The drawn point the close view at t_s is centred on: the wheel's drawn
  /// lowest point (following), or the middle of its range over the window
  /// (fixed camera).
  virtual Eigen::Vector3d focus_at(double t_s) const {
    if (!setup_.settings.follow_wheel) return setup_.fixed_focus_m;
    return setup_.exaggeration.lowest_wheel_point(sample_at(setup_.trajectory, t_s).centre_m, setup_.wheel_radius_m);
  }
  /// The camera of the close view at t_s (side, top, or the perspective inset).
  virtual Camera camera_at(double t_s) const { return make_camera(setup_.settings, setup_.framing, focus_at(t_s)); }

 protected:
  /// Checks and measures the input (CrossingSetup); each view's constructor then opens the GL context.
  CrossingView(const RenderSettings& settings, const RailJointMesh& rails, const TriangleMesh& wheel,
               const Trajectory& trajectory)
      : setup_(settings, rails, wheel, trajectory) {}

  /// (t_s) => the meshes that change from frame to frame (the top view's running band).
  virtual void update_meshes(double /*t_s*/) {}
  /// (t_s) => the scenes and the overlay (labels, borders, scale bars, legend) of the frame.
  virtual FrameDrawList frame_at(double t_s) const = 0;

  /// The scene of a close view (side, top) seen by `camera`, its key light
  /// from the viewer's side of the track, above and a little behind: the
  /// `ground` mesh and the rails, drawn through the exaggeration.
  SceneDraw close_scene(const Camera& camera, MeshHandle ground) const {
    SceneDraw scene = scene_seen_by(camera, Eigen::Vector3f(-0.35f, -0.8f, 0.5f).normalized());
    const Eigen::Matrix4f e = setup_.exaggeration.matrix().cast<float>();
    scene.meshes = {{ground, e}, setup_.rails_draw(e)};
    return scene;
  }

  CrossingSetup setup_;
};

}  // namespace railjoint
