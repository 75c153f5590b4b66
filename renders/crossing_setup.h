#pragma once
// What the three views of a recorded crossing share (renders/crossing_view.h):
// the checked settings and trajectory, the frame window, the exaggeration
// map, the rails' and the wheel's measurements, the straightedge, and the GL
// context with the meshes every view draws (rails, wheel body, the close
// views' wheel marks). A view owns one and adds its own meshes and layout.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "geometry/rail_joint_mesh.h"
#include "geometry/triangle_mesh.h"
#include "renders/camera.h"
#include "renders/crossing_meshes.h"
#include "renders/frame_schedule.h"
#include "renders/offscreen_renderer.h"
#include "renders/render_settings.h"
#include "renders/vertical_exaggeration.h"
#include "sim/trajectory.h"

namespace railjoint {

/// The ground under the rails, in real coordinates: from x_lo_m to x_hi_m,
/// |y| <= y_half_m, at height z_m (2 mm drawn below the rail bottoms).
struct GroundPlane {
  double x_lo_m = 0.0, x_hi_m = 0.0, y_half_m = 0.0, z_m = 0.0;
};

struct CrossingSetup {
  /// Checks the settings and the window against the trajectory (InputError)
  /// and the meshes (std::invalid_argument), and measures them. No GL yet.
  CrossingSetup(const RenderSettings& settings, const RailJointMesh& rails, const TriangleMesh& wheel,
                const Trajectory& trajectory);

  /// Creates the GL context and uploads the shared meshes: `rails` (as the
  /// view cuts them), the wheel body, and the close view's wheel marks for a view `view_width_m`
  /// wide at px_per_m image pixels per drawn metre.
  void open_gl(const std::vector<MeshVertex>& rails, const TriangleMesh& wheel, double view_width_m, double px_per_m);

  /// The first impact within one frame period of t_s, if any (the last such).
  const ImpactEvent* impact_within_one_frame(double t_s) const;
  /// Text scale of the labels: stb_easy_font's glyphs are about 7 px tall, 2x at 720p.
  float text_scale() const;
  /// Width of the orange border round an impact frame [px].
  float impact_border_px() const;
  /// The ground as a checker of 0.1 m tiles aligned with world x, so that a following camera shows the motion.
  std::vector<MeshVertex> checker_ground() const;
  /// The path of the wheel's lowest point, just in front of the wheel's near face.
  std::vector<LineVertex> lowest_point_path() const;
  /// `path` (lowest_point_path's mesh) through `model` up to the last recorded sample at or before t_s.
  MeshDraw path_up_to(MeshHandle path, const Eigen::Matrix4f& model, double t_s) const;
  /// The rails through `model`, their back faces culled (closed solids).
  MeshDraw rails_draw(const Eigen::Matrix4f& model) const;
  /// The close view's wheel at `sample`, body and marks, through the exaggeration.
  void append_close_wheel(SceneDraw& scene, const WheelSample& sample) const;
  /// Diameter of the close views' contact markers [px].
  float close_marker_px() const;

  RenderSettings settings;
  Trajectory trajectory;
  FrameWindow window;
  VerticalExaggeration exaggeration;
  CameraFraming framing;
  double wheel_radius_m = 0.0;
  double wheel_half_width_m = 0.0;
  double wheel_y_m = 0.0;       ///< lateral position of the first sample (the carrier holds y)
  double face_offset_m = 0.0;   ///< how far outside the wheel's faces its decorations lie
  double rail_half_width_m = 0.0;
  double rail_top_max_m = 0.0;
  Eigen::AlignedBox3d rail_box_m;       ///< drawn (exaggerated)
  Eigen::AlignedBox3d rail_box_real_m;  ///< real
  double window_x_lo_m = 0.0, window_x_hi_m = 0.0;  ///< the wheel centre's x over the window
  Eigen::Vector3d fixed_focus_m = Eigen::Vector3d::Zero();  ///< the middle of the drawn lowest point's range
  GroundPlane ground;
  Straightedge straightedge;

  std::unique_ptr<OffscreenRenderer> gl;
  MeshHandle rails_mesh = -1, wheel_mesh = -1, close_marks_mesh = -1;
};

/// A scene seen by `camera`, lit from `to_light`, on the background colour; no meshes yet.
SceneDraw scene_seen_by(const Camera& camera, const Eigen::Vector3f& to_light);

/// The wheel's pose at `sample`: its centre and spin about the axle.
Eigen::Matrix4f wheel_pose(const WheelSample& sample);

/// The touching contacts of `sample` (magenta), the impact within one frame
/// period of t_s (a big ring) and earlier impacts (small dots), drawn through
/// the exaggeration when `exaggerated`, else at their real places.
void append_contact_markers(SceneDraw& scene, const CrossingSetup& setup, double t_s, const WheelSample& sample,
                            float marker_px, bool exaggerated);

/// Pixel (origin top-left) of a point seen by `camera` in `rect`.
Eigen::Vector2f project_to_pixel(const Camera& camera, const PixelRect& rect, const Eigen::Vector3d& point_m);

}  // namespace railjoint
