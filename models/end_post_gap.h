#pragma once
// The end-post gap of the local model (thesis section 5.2, figure 5.1) seen
// from above: a parallelogram between the two rail ends, in the thesis's
// frame (origin at the gap's corner where the patch enters, x along the
// track in the direction of travel, y across the patch, 0 <= y <= b).
// Its nominal width g is measured normal to the cut (the same meaning as
// `joint.gap`); along the track it is g_long = g / sin(theta) long.

#include <array>

#include <Eigen/Core>

namespace railjoint {

struct EndPostGap {
  double gap_m = 0.006;               ///< nominal gap g, normal to the cut [m] (table 6.1: 6 mm)
  double theta_rad = 0.5235987755982988;  ///< junction angle between the cut and the x axis [rad]; pi/2 = square joint
};

/// g_long = g / sin(theta) [m]: the gap's length along the track.
double longitudinal_gap_m(const EndPostGap& gap);

/// Unit normal of the cut pointing from the incoming rail end into the gap,
/// n = (sin theta, -cos theta): the incoming rail end is n.p < 0, the gap
/// 0 <= n.p <= g, the outgoing rail end n.p > g.
Eigen::Vector2d cut_normal(const EndPostGap& gap);

/// The thesis's four vertices for a band of width `width_m` (the patch width b),
/// counter-clockwise: P_tl (0, 0), P_tr (g_long, 0), P_br (b cot(theta) + g_long, b),
/// P_bl (b cot(theta), b) [m].
std::array<Eigen::Vector2d, 4> gap_parallelogram_m(const EndPostGap& gap, double width_m);

}  // namespace railjoint
