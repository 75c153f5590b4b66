#pragma once
// Draws a recorded wheel crossing the rail joint, one frame per call, in one
// of three views, each its own class: the side view (renders/side_view.h),
// the top view (renders/top_view.h) and the perspective view
// (renders/perspective_view.h), behind renders/crossing_view.h. What they
// share, the checked input, the exaggeration map, the GL context and the
// common meshes, is set up once here (renders/crossing_setup.h). Both stay
// out of this header: callers see only the renderer.

#include <memory>
#include <optional>
#include <string>

#include "geometry/rail_joint_mesh.h"
#include "geometry/triangle_mesh.h"
#include "renders/camera.h"
#include "renders/frame_schedule.h"
#include "renders/joint_contact_patch.h"
#include "renders/offscreen_renderer.h"
#include "renders/render_settings.h"
#include "renders/rgb_image.h"
#include "sim/trajectory.h"

namespace railjoint {

struct CrossingSetup;
class CrossingView;
class PerspectiveView;
class TopView;

class CrossingRenderer {
 public:
  /// Checks the settings and the window against the trajectory (InputError),
  /// the meshes (std::invalid_argument; the rails must be convex solids for
  /// the side view's section), then creates the GL context (std::runtime_error
  /// when it is not built or refuses). The wheel mesh is
  /// centred at the origin with its axle along y; its radius and half-width
  /// are read from it. Use a fine one (renders/wheel_tessellation.h): a
  /// coarse polygon shows its facets, k times magnified, in the contact view.
  /// The trajectory is copied.
  CrossingRenderer(const RenderSettings& settings, const RailJointMesh& rails, const TriangleMesh& wheel,
                   const Trajectory& trajectory);
  ~CrossingRenderer();

  const FrameWindow& window() const;
  const std::string& gl_version() const;
  const std::string& gl_renderer() const;

  /// Top view only (ignored by the others): TopView::show_contact_patch.
  void show_contact_patch(const PressureInputs& inputs);
  /// Where the patch lies at t_s; nothing when none is shown, the wheel is in
  /// flight or the view is not the top view.
  std::optional<PatchPlacement> contact_patch_at(double t_s) const;

  /// Frame k of the window (0 <= k < window().count).
  void render_frame(long long k, RgbImage& out);
  /// Frame k drawn and read back, not finished: finish_frame() makes the
  /// picture, on another thread if wanted (render_crossing.cpp).
  void draw_frame(long long k, ReadBackFrame& out);
  /// Any instant (clamped to the trajectory's ends).
  void render_at(double t_s, RgbImage& out);
  void draw_at(double t_s, ReadBackFrame& out);

  /// CrossingView::focus_at and camera_at of the view drawn.
  Eigen::Vector3d focus_at(double t_s) const;
  Camera camera_at(double t_s) const;

  /// The perspective view (its overview camera, layout and straightedge), or nullptr in the other views.
  const PerspectiveView* perspective() const;

 private:
  TopView* top() const;

  std::unique_ptr<CrossingSetup> setup_;
  std::unique_ptr<CrossingView> view_;  ///< refers to *setup_
};

}  // namespace railjoint
