#pragma once
// The exact kinematic path of the wheel centre: the wheel "glued" to the rail
// (no inertia), horizontal speed held, centre at the lowest height at which
// the wheel touches but does not cut the rails: the governing slice's
// profile where the thesis's model holds, the envelope over all slices
// (wheel_rail_envelope.h) elsewhere. Valid across the whole crossing
// (approach, jump, pivot, run-out).

#include <optional>

#include "models/parameters.h"
#include "models/slice_profile.h"

namespace railjoint {

/// The path of one joint and wheel, with the model it follows decided once:
/// for callers that read it at many x (deciding costs a contact solve where
/// there is a gap, models/finite_width_wheel.h).
class KinematicPath {
 public:
  KinematicPath(const JointParams& joint, const WheelParams& wheel);

  /// Height of the wheel centre [m] when the centre is at x = wheel_x_m.
  double centre_height_m(double wheel_x_m) const;

  /// d z / d x of the path [-]; at a kink, the one-sided slope from the given side (+1 after, -1 before).
  double centre_slope(double wheel_x_m, int side = +1) const;

 private:
  struct RailHeights {
    double incoming_z_m, incoming_slope;
    double outgoing_z_m, outgoing_slope;
  };
  RailHeights rail_heights(double wheel_x_m) const;

  JointParams joint_;
  WheelParams wheel_;
  std::optional<SliceProfile> governing_profile_;  ///< the thesis's model; empty: the general one
};

/// KinematicPath(joint, wheel).centre_height_m(wheel_x_m), for a single read.
double kinematic_centre_height_m(const JointParams& joint, const WheelParams& wheel, double wheel_x_m);

/// KinematicPath(joint, wheel).centre_slope(wheel_x_m, side), for a single read.
double kinematic_centre_slope(const JointParams& joint, const WheelParams& wheel, double wheel_x_m, int side = +1);

}  // namespace railjoint
