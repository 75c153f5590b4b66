#pragma once
// The dip: how the two rail ends of an inclined joint are deflected along x
// (thesis fig. 2.3). The kinematic model uses the linear dip, each rail end
// inclined by beta/2 with the V bottom at x = 0. A quadratic or sinusoidal dip
// is added here (height, slope and how finely its top must be meshed, with a
// shape key in JointParams and the scene reader); the rail top (rail_top.h),
// the slice profile of the model and the meshes all read the dip from here.

#include "models/parameters.h"

namespace railjoint {

/// Height of the top of rail 0 (incoming) or 1 (outgoing) at x, as if it ran on
/// past the cut [m]. Linear: incoming -tan(beta/2) x, outgoing +tan(beta/2) x.
double dip_height_m(const JointParams& joint, int rail, double x_m);

/// d(dip_height_m)/dx [-].
double dip_slope(const JointParams& joint, int rail, double x_m);

/// Pieces along x the top of one rail end is divided into by the mesh builder.
/// Linear: 1, the top is one plane and two triangles represent it exactly.
int dip_pieces_along_x(const JointParams& joint);

}  // namespace railjoint
