#pragma once
// The local model's contact patch (thesis chapters 5-6) laid on the global
// scene's joint, for the top view: where the patch under the wheel lies, how
// much of it is over the end-post gap, and the pressure that gives.
//
// The two frames. The global scene's cut runs along x = y cot(theta) and the
// gap g (normal to the cut) moves each rail end back by g / (2 sin theta)
// along x (models/parameters.h, models/inclined_joint.h): at lateral y the gap
// spans x in [y cot(theta) - g_long / 2, y cot(theta) + g_long / 2], g_long =
// g / sin(theta). The local model's frame (models/end_post_gap.h) has its
// origin at the gap's corner where the patch enters and the patch across
// 0 <= y_l <= b: there the gap spans x_l in [y_l cot(theta), y_l cot(theta) +
// g_long]. Both measure x in the direction of travel and turn the cut the
// same way, so they differ by a shift: x = x_l + x0, y = y_l + y0, with y0 the
// patch's lower edge (its centre's y minus b/2) and, matching the gaps' near
// edges at y_l = 0, x0 = y0 cot(theta) - g_long / 2.
//
// The patch is centred on the wheel's contact: along x at the contact point
// on the rail (the global model's, so the patch sits where the drawn contact
// marker is), across at the wheel's lateral position, moved inwards just
// enough to lie whole on the rail head (the local model takes the patch whole
// on the head). Its front is then at x_front = x_c - x0 + a/2.

#include <vector>

#include <Eigen/Core>

#include "models/pressure_traversal.h"
#include "renders/offscreen_renderer.h"

namespace railjoint {

struct PatchPlacement {
  double x_front_m = 0.0;                              ///< the local model's x_front [m]
  Eigen::Vector2d local_origin_m = Eigen::Vector2d::Zero();  ///< (x0, y0): global = local + origin [m]
  PressureState state;                                 ///< R, A, P at x_front
};

/// The patch of `inputs` centred at global (x_c, y_c) (y_c moved onto a rail
/// head of half-width b_t if the patch would overhang it).
PatchPlacement place_contact_patch(const PressureInputs& inputs, const Eigen::Vector2d& centre_m, double rail_half_width_m);

/// The placed patch as triangles lying at height z_m: the whole patch in
/// palette::patch_bearing, and its part over the gap in palette::patch_over_gap
/// a hair (1 um) above it, so the red covers the teal there.
std::vector<MeshVertex> contact_patch_vertices(const PressureInputs& inputs, const PatchPlacement& placement, double z_m);

}  // namespace railjoint
