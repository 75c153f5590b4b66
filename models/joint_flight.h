#pragma once
// Whether, where and for how long a loaded wheel flies at the joint (the
// lift-off model of liftoff.h applied to the kinematic model's corner), so a
// simulation of the wheel in service can be made long enough to see it land.
// Horizontal speed v held, constant vertical load W (weight + axle load).
//
// The wheel pivots about the corner A of the prediction (ImpactPrediction::
// contact_A_m): after a scenario-2 or step-up strike the corner it struck,
// from the radius angle -alpha on (the demand is largest there, so it flies
// at once or not at all); on the step-down side the end of the incoming
// rail, from the incoming slope's angle to the landing (the demand grows as
// it rolls over). It leaves the arc at the first angle phi with
// v > v_c(phi), with the arc's velocity, and flies on a parabola under
// W / M until the parabola meets the kinematic centre path again.

#include "models/impact_prediction.h"
#include "models/parameters.h"

namespace railjoint {

struct JointFlight {
  bool flies = false;
  double liftoff_x_m = 0.0;   ///< centre x where it leaves the corner [m]
  double landing_x_m = 0.0;   ///< centre x where it meets the centre path again [m]
  double duration_s = 0.0;    ///< (landing_x - liftoff_x) / v [s]
  double apex_height_m = 0.0; ///< highest rise above the lift-off height [m]
};

/// `wheel`: the slice the prediction was made for; `vertical_load_N`: W > 0.
/// No flight for scenario 1 (no convex corner) or below the lift-off speed.
JointFlight predict_joint_flight(const JointParams& joint, const WheelParams& wheel,
                                 const ImpactPrediction& prediction, double vertical_load_N);

}  // namespace railjoint
