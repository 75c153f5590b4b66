#pragma once
// Where a wheel rests on the incoming rail: its centre, given where it touches.
// Shared by the mesh CLI, the renderer and the simulation's start state.

#include <Eigen/Core>

#include "models/parameters.h"

namespace railjoint {

/// Centre of the wheel (in its plane y = y_w) touching the incoming rail top at
/// x = contact_x [m]: the contact point plus R along the top's upward normal,
/// (-m, 0, 1) / sqrt(1 + m^2) with m the top's slope there. Holds for any wheel
/// width, as the rail top does not vary with y.
Eigen::Vector3d wheel_centre_on_incoming_rail_m(const JointParams& joint, const WheelParams& wheel, double contact_x_m);

}  // namespace railjoint
