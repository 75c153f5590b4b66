#pragma once
// The exact rail-top surface of a joint, shared by the mesh builder, the
// simulation, the renderer and the tests: where each rail ends at the cut and
// how high its top is. Coordinates of models/DESIGN.md "Coordinates and symbols" (x along
// travel, y lateral, z up, V bottom of the dip at x = 0).

#include "models/parameters.h"

namespace railjoint {

/// x of the cut face of rail 0 (incoming) or 1 (outgoing) at lateral y [m].
/// Inclined: y cot(theta) -/+ g / (2 sin theta), the gap g being measured
/// normal to the cut. Step: the cut is square, -/+ g / 2 (theta ignored).
double cut_x_m(const JointParams& joint, double y_m, int rail);

/// Height of the top of rail 0 or 1 at x, as if it ran on past its cut [m]:
/// the dip (dip_profile.h) for an inclined joint; 0 (incoming) or u0
/// (outgoing) for a step joint.
double rail_surface_height_m(const JointParams& joint, int rail, double x_m);

/// d(rail_surface_height_m)/dx [-].
double rail_surface_slope(const JointParams& joint, int rail, double x_m);

/// Height of the rail top at (x, y) [m], the head's crown (rail_head.h) plus
/// the dip: the incoming rail for
/// -L/2 <= x <= cut_x_m(y, 0), the outgoing one for cut_x_m(y, 1) <= x <= L/2
/// (on the cut line of a gapless joint: the incoming rail). NaN where there is
/// no rail: inside the gap, |y| > b_t, |x| > L/2.
double rail_top_height_m(const JointParams& joint, double x_m, double y_m);

}  // namespace railjoint
