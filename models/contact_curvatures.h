#pragma once
// The principal curvatures of wheel and rail where they touch, from the
// surfaces the whole program shares (wheel_tread.h: radius, cone or
// measured tread; rail_head.h: crown, 60E1 or measured head; rail_top.h:
// the dip): one derivation for every Hertz ellipse, the force run's
// (sim/force_contact_geometry.h) and the solved contact's grid
// (rail_end_contact.h).

#include "models/hertz_ellipse.h"
#include "models/parameters.h"

namespace railjoint {

/// Half the step of the central differences of the profiles' slopes: their
/// second derivatives (curvatures of 1/0.013 m at most on 60E1) to some
/// 1e-9 from the difference's h^2 term and the slopes' round-off over 2h;
/// a 1 um window straddles a 60E1 arc join for only that long [m].
inline constexpr double kCurvatureStep_m = 1e-6;

/// The curvatures at (x, y) on rail 0 or 1: the rolling circle's by
/// Meusnier, cos(psi) / r with psi = atan(r') the angle between the tread's
/// normal and the slice's radius; the tread's and the head's transverse
/// ones and the dip's longitudinal one as the normal curvatures of their
/// graphs, -f'' / (1 + f'^2)^(3/2), convex positive.
ContactCurvatures contact_curvatures_at(const JointParams& joint, const WheelParams& wheel, int rail, double x_m,
                                        double y_m);

}  // namespace railjoint
