#pragma once
// The rail head's top across the track (thesis section 7.2.1: the lateral
// curvature the thesis leaves out). A crowned head is a circular arc of
// radius rho across y with its crest on the centre line, y = 0:
//   z(y) = sqrt(rho^2 - y^2) - rho  (<= 0; 0 for a flat head, the thesis).
// Every lateral line of the head carries the same dip along x
// (dip_profile.h), so the rail top is z(y) + dip(x).

#include "models/parameters.h"

namespace railjoint {

/// A flat head (crown_radius_m = 0), as the thesis has it.
bool has_flat_head(const JointParams& joint);

/// Height of the head's top at lateral y below its crest [m] (<= 0).
double head_top_height_m(const JointParams& joint, double y_m);

/// d(head_top_height_m)/dy [-].
double head_top_slope(const JointParams& joint, double y_m);

}  // namespace railjoint
