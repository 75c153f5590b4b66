#pragma once
// The side view: a section through the wheel's width at the lateral position
// of the first sample (the carrier holds y; renders/slab_section.h), the two
// rail solids cut to it (top, cut and side faces in different colours), the
// wheel (rim ticks, a dark bar and a knob so its spin shows), the path of the
// wheel's lowest point so far, the contact points of the nearest recorded
// sample, the impacts, a ground checker, a datum line at the reference height
// behind everything, scale bars and labels. Everything, the wheel included,
// is drawn through the one affine map of VerticalExaggeration, so the drawn
// wheel (an ellipse k times taller than wide) touches the drawn rails exactly
// where the real wheel touches the real rails and overlaps them only where it
// really does.

#include <optional>

#include "renders/crossing_view.h"
#include "renders/side_view_framing.h"

namespace railjoint {

class SideView final : public CrossingView {
 public:
  /// As CrossingView::make; throws std::invalid_argument when the wheel mesh
  /// has no width to cut the rails to. A flight the default width cannot show
  /// with the rails under it widens the view for the whole render (when
  /// following; a width the scene gives is kept).
  SideView(const RenderSettings& settings, const RailJointMesh& rails, const TriangleMesh& wheel,
           const Trajectory& trajectory);

  Eigen::Vector3d focus_at(double t_s) const override;
  FrameDrawList frame_at(double t_s) const override;

 private:
  SideViewFraming framing_;  ///< where it looks in a flight
  double px_per_m_ = 1.0;    ///< image pixels per drawn metre
  MeshHandle ground_ = -1, datum_ = -1, path_ = -1;
};

}  // namespace railjoint
