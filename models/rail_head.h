#pragma once
// The rail head's top across the track (thesis section 7.2.1: the lateral
// curvature the thesis leaves out), as a height below its crest at y = 0:
//  - flat (the thesis): 0;
//  - crowned: one circular arc of radius rho, sqrt(rho^2 - y^2) - rho;
//  - 60E1 (EN 13674-1:2011, the 60E1 profile drawing): tangent arcs of
//    300 mm for |y| <= 10.228 mm, 80 mm to |y| = 26.0265 mm, then 13 mm down
//    to where the head's side leans 1:20 from the vertical, |y| = 36.000 mm
//    (the 72 mm head). The two widths, 20.456 and 52.053 mm, are the
//    drawing's chords of the 300 and 80 mm arcs (as transcribed in the
//    EN13674 profile package, github.com/rohrbecka/EN13674); the 13 mm arc's
//    end follows from them and lands on the standard's 72 mm head width;
//  - measured: (y, z) points (profile_curve.h), less their highest z.
// Every lateral line of the head carries the same dip along x
// (dip_profile.h), so the rail top is z(y) + dip(x). The drawn profiles are
// concave in y, which the general model's root search relies on; a measured
// one need not be, and the model searches it first (wheel_rail_envelope.h).

#include "models/parameters.h"

namespace railjoint {

/// A flat head (an arc of radius 0), as the thesis has it.
bool has_flat_head(const JointParams& joint);

/// Height of the head's top at lateral y below its crest [m] (<= 0).
double head_top_height_m(const JointParams& joint, double y_m);

/// d(head_top_height_m)/dy [-].
double head_top_slope(const JointParams& joint, double y_m);

/// Half the width of the head's top the profile describes [m]: infinite for
/// an arc (its radius must exceed joint.half_width), 36 mm for 60E1 (the 13
/// mm arc meets the 1:20 side at 35.9998 mm), what a measured profile covers
/// either side of y = 0.
double head_profile_half_width_m(const JointParams& joint);

}  // namespace railjoint
