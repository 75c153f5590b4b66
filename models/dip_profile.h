#pragma once
// The dip: how the two rail ends of a joint droop towards it along x (thesis
// fig. 2.3), the V bottom at x = 0 and height 0. Every shape meets the joint
// at the slope tan(beta/2) on each side (beta the total angle at the joint).
// With t = tan(beta/2) and s the distance from the V back along a rail end
// (s = -x on the incoming rail, s = x on the outgoing one), the height is
//   linear:     t s                                  (the thesis; every s)
//   quadratic:  t s - t s^2 / (2 D)   for 0 <= s <= D, t D / 2 beyond
//   cosine:     (2 t D / pi) sin(pi s / (2 D))  for 0 <= s <= D, 2 t D / pi beyond
// D = joint.dip_length. The quadratic is the parabolic droop measured on
// dipped joints; the cosine a quarter wave, as railway codes write a joint's
// irregularity, with zero slope where it starts. Where a rail end runs past
// the V (s < 0: an inclined cut reaches beyond x = 0) it goes on straight,
// t s. Each shape is concave on each rail end, which the general kinematic
// model (models/wheel_rail_envelope.h) relies on. The rail top (rail_top.h),
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

const char* to_string(DipShape shape);

/// A dip as measured with a straight edge: its depth d below the level rail
/// either side [m], over dip_length D on each rail end (L = 2 D overall).
/// The level lies where the droop ends, s = D: d = t D / 2 (quadratic),
/// d = 2 t D / pi (cosine); linear has no level and no depth.
double dip_depth_m(DipShape shape, double beta_rad, double dip_length_m);

/// The total angle beta at the joint that gives depth d over dip_length D:
/// the inverse of dip_depth_m, beta = 2 atan(2 d / D) (quadratic),
/// 2 atan(pi d / (2 D)) = 2 atan(pi d / L) (cosine) [rad].
double dip_angle_from_depth_rad(DipShape shape, double depth_m, double dip_length_m);

}  // namespace railjoint
