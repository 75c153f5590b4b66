#pragma once
// The exact kinematic path of the wheel centre: the wheel "glued" to the rail
// (no inertia), horizontal speed held, centre at the lowest height at which
// the wheel circle touches but does not cut the rail profile of the governing
// slice. Valid across the whole crossing (approach, jump, pivot, run-out).

#include "models/parameters.h"

namespace railjoint {

/// Height of the wheel centre [m] when the centre is at x = wheel_x_m.
double kinematic_centre_height_m(const JointParams& joint, const WheelParams& wheel, double wheel_x_m);

/// d z / d x of that path [-]; at a kink, the one-sided slope from the given side (+1 after, -1 before).
double kinematic_centre_slope(const JointParams& joint, const WheelParams& wheel, double wheel_x_m, int side = +1);

}  // namespace railjoint
