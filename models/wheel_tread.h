#pragma once
// The wheel's tread across its width: a surface of revolution about the axle,
// so each thin slice at lateral y is a circle of radius r(y). A conical tread
// of conicity kappa (tan of the cone angle) has
//   r(y) = R - kappa (y - y_w),
// R the rolling radius at the wheel's lateral position y_w, larger towards -y
// (the flange side); kappa = 0 is the thesis's cylinder. A measured tread
// (WheelParams::measured_tread, y from the wheel's plane) replaces the cone.

#include "models/parameters.h"

namespace railjoint {

/// A cylinder (conicity 0, no measured tread), as the thesis has it.
bool has_cylindrical_tread(const WheelParams& wheel);

/// Radius of the wheel's slice at lateral y [m].
double tread_radius_m(const WheelParams& wheel, double y_m);

/// d(tread_radius_m)/dy at lateral y [-].
double tread_radius_slope(const WheelParams& wheel, double y_m);

}  // namespace railjoint
