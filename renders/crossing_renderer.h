#pragma once
// Draws a recorded wheel crossing the rail joint, one frame per call: the two
// rail solids (top, cut and side faces in different colours), the wheel (with
// a dark bar and a knob so its spin shows), the wheel-centre path so far, the
// contact points of the nearest recorded sample, the impacts (a big marker,
// an orange border and a label on frames within one frame period of an
// impact, a small marker afterwards), a ground checker, a datum line at the
// reference height with ticks every 50 mm, and a time label.
// Everything is drawn through the VerticalExaggeration of the settings.

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
  /// Checks the settings and the window against the trajectory (ParameterError),
  /// the meshes (std::invalid_argument), then creates the GL context
  /// (std::runtime_error without OSMesa). The wheel mesh is centred at the
  /// origin with its axle along y; its radius and half-width are read from it.
  /// The trajectory is copied.
  CrossingRenderer(const RenderSettings& settings, const RailJointMesh& rails, const TriangleMesh& wheel,
                   const Trajectory& trajectory);
  ~CrossingRenderer();

  const FrameWindow& window() const { return window_; }
  const VerticalExaggeration& exaggeration() const { return exaggeration_; }
  const std::string& gl_version() const;
  const std::string& gl_renderer() const;

  /// Frame k of the window (0 <= k < window().count).
  void render_frame(long long k, RgbImage& out);
  /// Any instant (clamped to the trajectory's ends).
  void render_at(double t_s, RgbImage& out);

  /// The camera used for a frame at t_s.
  Camera camera_at(double t_s) const;

 private:
  FrameDrawList frame_at(double t_s) const;

  RenderSettings settings_;
  Trajectory trajectory_;
  FrameWindow window_;
  VerticalExaggeration exaggeration_;
  CameraFraming framing_;
  double wheel_half_width_m_ = 0.0;
  double fixed_centre_x_m_ = 0.0;
  std::unique_ptr<OffscreenRenderer> gl_;
  MeshHandle rails_ = -1, ground_ = -1, datum_ = -1, wheel_ = -1, path_ = -1;
};

}  // namespace railjoint
