#pragma once
// The top view: the rails from above with the cut on the rail head, the
// wheel drawn translucent over the running band (the strip of rail head it
// has touched so far: a line for a thin disc, its width for a cylinder, with
// gaps where it flew), the contact points, the impacts, a ground checker,
// a scale bar and labels; optionally the local model's contact patch.

#include <optional>

#include "models/pressure_traversal.h"
#include "renders/crossing_view.h"
#include "renders/joint_contact_patch.h"

namespace railjoint {

class TopView final : public CrossingView {
 public:
  /// As CrossingView::make.
  TopView(const RenderSettings& settings, const RailJointMesh& rails, const TriangleMesh& wheel,
          const Trajectory& trajectory);

  /// From now on draw the local model's contact patch at the wheel's contact
  /// on every frame where the wheel touches the rails, its part over the
  /// end-post gap in red, and its size, A/A0 and pressure in the legend
  /// (renders/joint_contact_patch.h). `inputs` must have passed check_pressure_inputs.
  void show_contact_patch(const PressureInputs& inputs);
  /// Where the patch lies at t_s; nothing when none is shown or the wheel is in flight.
  std::optional<PatchPlacement> contact_patch_at(double t_s) const;

  void update_meshes(double t_s) override;
  FrameDrawList frame_at(double t_s) const override;

 private:
  double px_per_m_ = 1.0;  ///< image pixels per drawn metre
  std::optional<PressureInputs> contact_patch_;
  MeshHandle ground_ = -1, band_ = -1, cut_line_ = -1, patch_ = -1;
};

}  // namespace railjoint
