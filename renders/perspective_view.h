#pragma once
// The perspective view: the whole wheel standing on both rail ends, TO SCALE
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

#include <optional>

#include "renders/crossing_view.h"

namespace railjoint {

class PerspectiveView final : public CrossingView {
 public:
  /// As CrossingView::make.
  PerspectiveView(const RenderSettings& settings, const RailJointMesh& rails, const TriangleMesh& wheel,
                  const Trajectory& trajectory);

  /// The sides of the whole wheel drawn to scale in the overview (the inset draws the wheel mesh given).
  int overview_wheel_sides() const { return overview_wheel_sides_; }
  /// The whole-wheel camera (fixed over the window, real coordinates) and
  /// where its picture and the inset lie in the image.
  const Camera& overview_camera() const { return overview_camera_; }
  const PixelRect& overview_rect() const { return overview_rect_; }
  const PixelRect& inset_rect() const { return inset_rect_; }

  /// The inset's camera.
  Camera camera_at(double t_s) const override;
  FrameDrawList frame_at(double t_s) const override;

 private:
  SceneDraw overview_scene(double t_s, const WheelSample& sample) const;
  SceneDraw inset_scene(double t_s, const WheelSample& sample) const;
  void append_labels(FrameDrawList& list, double t_s, const WheelSample& sample, const ImpactEvent* current) const;
  /// Pixel (origin top-left) of a real point in the overview.
  Eigen::Vector2f project_overview(const Eigen::Vector3d& point_m) const;

  Camera overview_camera_;
  PixelRect overview_rect_, inset_rect_, legend_rect_;
  int overview_wheel_sides_ = 0;
  MeshHandle path_ = -1, plain_ground_ = -1, whole_marks_ = -1, joint_marks_ = -1, dished_wheel_ = -1;
};

}  // namespace railjoint
