#pragma once
// The solved crossing (rail_end_contact.h) with every step's whole field
// handed over as it is solved: what `pressure --frames` draws. Apart from
// rail_end_contact.h so that the crossing's many readers do not see it.

#include <functional>

#include <Eigen/Core>

#include "models/rail_end_contact.h"

namespace railjoint {

/// One step's grid and pressure (an empty grid for a step in flight).
struct RailEndField {
  RailEndStep step;
  RailEndGap gap;
  Eigen::ArrayXXd pressure_Pa;
};

using RailEndFieldObserver = std::function<void(const RailEndField&)>;

/// rail_end_crossing under a load history, calling `observe` after each step.
RailEndCrossing rail_end_crossing_observed(const JointParams& joint, const WheelParams& wheel,
                                           const RailEndContactSettings& settings, const NormalForceAt& normal_force_N,
                                           double sizing_force_N, int steps, const RailEndFieldObserver& observe);

}  // namespace railjoint
