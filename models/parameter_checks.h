#pragma once
// Checks that a joint and wheel describe a case the kinematic model covers.
// Throws ParameterError naming the scene key at fault.

#include "models/parameters.h"

namespace railjoint {

void check_parameters(const JointParams& joint, const WheelParams& wheel);

}  // namespace railjoint
