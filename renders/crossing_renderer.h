#pragma once
// Draws a recorded wheel crossing the rail joint, one frame per call.
//
// Side and top views (the close views): the two rail solids (top, cut and
// side faces in different colours), the wheel (rim ticks, a dark bar and a
// knob so its spin shows), the path of the wheel's lowest point so far, the
// contact points of the nearest recorded sample, the impacts (a big ring, an
// orange border and a label on frames within one frame period of an impact,
// a small dot afterwards), a ground checker, a datum line at the reference
// height behind everything, scale bars and labels. Everything, the wheel
// included, is drawn through the one affine map of VerticalExaggeration, so
// the drawn wheel (an ellipse k times taller than wide in the side view)
// touches the drawn rails exactly where the real wheel touches the real
// rails and overlaps them only where it really does. The side view is a
// section through the wheel's width at the lateral position of the first
// sample (the carrier holds y; renders/slab_section.h). The top view draws
// the wheel translucent over the running band: the strip of rail head it has
// touched so far (a line for a thin disc, its width for a cylinder), with
// gaps where it flew.
//
// Perspective view: the whole wheel standing on both rail ends, TO SCALE
// (no exaggeration: an affine stretch would make the wheel an ellipse), seen
// from above the incoming rail on the side the cut faces, the camera placed
// so the wheel and the rails near it fill the left part of the picture
// (renders/camera.h fit_perspective_camera); a straightedge laid on the two
// rail ends shows the dip as the gap under it. On the right, an inset of the
// contact region drawn with the k-fold exaggeration (stated in its caption),
// following the wheel's lowest point, and the legend below it, so neither
// covers the wheel or the contact. The wheel's rim is lit as a cylinder
// (smooth normals, a highlight), its faces flat, with a darker tyre band and
// a hub.

#include <memory>
#include <optional>
#include <string>

#include "geometry/rail_joint_mesh.h"
#include "geometry/triangle_mesh.h"
#include "renders/camera.h"
#include "renders/crossing_meshes.h"
#include "renders/frame_schedule.h"
#include "renders/joint_contact_patch.h"
#include "renders/offscreen_renderer.h"
#include "renders/render_settings.h"
#include "renders/rgb_image.h"
#include "renders/side_view_framing.h"
#include "renders/vertical_exaggeration.h"
#include "sim/trajectory.h"

namespace railjoint {

class CrossingRenderer {
 public:
  /// Checks the settings and the window against the trajectory (InputError),
  /// the meshes (std::invalid_argument; the rails must be convex solids for
  /// the side view's section), then creates the GL context of `backend`
  /// (absent: RAILJOINT_GL, gl_backend_from_environment; std::runtime_error
  /// when it is not built or refuses). The wheel mesh is
  /// centred at the origin with its axle along y; its radius and half-width
  /// are read from it. Use a fine one (renders/wheel_tessellation.h): a
  /// coarse polygon shows its facets, k times magnified, in the contact view.
  /// The trajectory is copied.
  CrossingRenderer(const RenderSettings& settings, const RailJointMesh& rails, const TriangleMesh& wheel,
                   const Trajectory& trajectory, std::optional<GlBackend> backend = std::nullopt);
  ~CrossingRenderer();

  const FrameWindow& window() const { return window_; }
  const std::string& gl_version() const;
  const std::string& gl_renderer() const;
  GlBackend gl_backend() const;
  /// Perspective view: the sides of the whole wheel drawn to scale in the
  /// overview (the inset draws the wheel mesh given); 0 in the other views.
  int overview_wheel_sides() const { return overview_wheel_sides_; }

  /// Top view only (ignored by the others): from now on draw the local
  /// model's contact patch at the wheel's contact on every frame where the
  /// wheel touches the rails, its part over the end-post gap in red, and its
  /// size, A/A0 and pressure in the legend (renders/joint_contact_patch.h).
  /// `inputs` must have passed check_pressure_inputs.
  void show_contact_patch(const PressureInputs& inputs);
  /// Where the patch lies at t_s; nothing when none is shown or the wheel is in flight.
  std::optional<PatchPlacement> contact_patch_at(double t_s) const;

  /// Frame k of the window (0 <= k < window().count).
  void render_frame(long long k, RgbImage& out);
  /// Frame k drawn and read back, not finished: finish_frame() makes the
  /// picture, on another thread if wanted (render_crossing.cpp).
  void draw_frame(long long k, ReadBackFrame& out);
  /// Any instant (clamped to the trajectory's ends).
  void render_at(double t_s, RgbImage& out);
  void draw_at(double t_s, ReadBackFrame& out);

  /// The drawn point the close view at t_s is centred on (the perspective
  /// view's inset): the wheel's drawn lowest point (following), or the middle
  /// of its range over the window (fixed camera).
  Eigen::Vector3d focus_at(double t_s) const;
  /// The camera of the close view at t_s (side, top, or the perspective inset).
  Camera camera_at(double t_s) const;

  /// Perspective view only: the whole-wheel camera (fixed over the window,
  /// real coordinates) and where its picture and the inset lie in the image.
  const Camera& overview_camera() const { return overview_camera_; }
  const PixelRect& overview_rect() const { return overview_rect_; }
  const PixelRect& inset_rect() const { return inset_rect_; }
  const Straightedge& straightedge() const { return straightedge_; }

 private:
  FrameDrawList frame_at(double t_s) const;
  SceneDraw close_scene(double t_s, const WheelSample& sample, const Camera& camera) const;
  SceneDraw overview_scene(double t_s, const WheelSample& sample) const;
  // Labels, borders, scale bars and the legend (crossing_labels.cpp).
  void append_close_view_labels(FrameDrawList& list, double t_s, const WheelSample& sample, const Camera& camera,
                                const ImpactEvent* current) const;
  void append_perspective_labels(FrameDrawList& list, double t_s, const WheelSample& sample,
                                 const ImpactEvent* current) const;
  const ImpactEvent* impact_within_one_frame(double t_s) const;
  float text_scale() const;
  /// Width of the orange border round an impact frame [px].
  float impact_border_px() const;
  /// Pixel (origin top-left) of a real point in the perspective overview.
  Eigen::Vector2f project_overview(const Eigen::Vector3d& point_m) const;
  /// Pixel of a drawn (exaggerated) point seen by `camera` in `rect`.
  static Eigen::Vector2f project(const Camera& camera, const PixelRect& rect, const Eigen::Vector3d& point_m);

  RenderSettings settings_;
  Trajectory trajectory_;
  FrameWindow window_;
  VerticalExaggeration exaggeration_;
  CameraFraming framing_;
  double wheel_radius_m_ = 0.0;
  double wheel_half_width_m_ = 0.0;
  double wheel_y_m_ = 0.0;
  double rail_half_width_m_ = 0.0;
  double rail_top_max_m_ = 0.0;
  Eigen::AlignedBox3d rail_box_real_;
  double px_per_m_ = 1.0;  ///< image pixels per drawn metre at the focus (close views)
  Eigen::Vector3d fixed_focus_m_ = Eigen::Vector3d::Zero();
  std::optional<SideViewFraming> side_framing_;  ///< the side view: where it looks in a flight
  Straightedge straightedge_;
  Camera overview_camera_;
  PixelRect overview_rect_, inset_rect_, legend_rect_;
  std::optional<PressureInputs> contact_patch_;  ///< the local model's patch, top view
  std::unique_ptr<OffscreenRenderer> gl_;
  MeshHandle rails_ = -1, ground_ = -1, datum_ = -1, wheel_ = -1, close_marks_ = -1, whole_marks_ = -1, path_ = -1,
             straightedge_bar_ = -1, band_ = -1, dished_wheel_ = -1, plain_ground_ = -1, patch_ = -1;
  int overview_wheel_sides_ = 0;
};

}  // namespace railjoint
