#include "models/kinematic_trajectory.h"

#include <algorithm>

#include "models/finite_width_wheel.h"
#include "models/wheel_rail_envelope.h"

namespace railjoint {

KinematicPath::KinematicPath(const JointParams& joint, const WheelParams& wheel) : joint_(joint), wheel_(wheel) {
  if (governing_slice_rule_holds(joint, wheel)) governing_profile_ = slice_profile(joint, governing_slice_y_m(joint, wheel));
}

KinematicPath::RailHeights KinematicPath::rail_heights(double wheel_x_m) const {
  if (governing_profile_) {
    const SegmentSupport in = segment_support((*governing_profile_)[0], wheel_.radius_m, wheel_x_m);
    const SegmentSupport out = segment_support((*governing_profile_)[1], wheel_.radius_m, wheel_x_m);
    return {in.centre_z_m, in.slope, out.centre_z_m, out.slope};
  }
  const RailSupport in = rail_support(joint_, wheel_, 0, wheel_x_m);
  const RailSupport out = rail_support(joint_, wheel_, 1, wheel_x_m);
  return {in.centre_z_m, in.slope, out.centre_z_m, out.slope};
}

double KinematicPath::centre_height_m(double wheel_x_m) const {
  const RailHeights h = rail_heights(wheel_x_m);
  return std::max(h.incoming_z_m, h.outgoing_z_m);
}

double KinematicPath::centre_slope(double wheel_x_m, int side) const {
  // At a kink the two rails hold the centre equally high; the side asked for
  // decides which one carries it an infinitesimal step away.
  const RailHeights h = rail_heights(wheel_x_m);
  const double tie_m = 1e-12 * std::max(1.0, wheel_.radius_m);
  if (h.outgoing_z_m > h.incoming_z_m + tie_m) return h.outgoing_slope;
  if (h.incoming_z_m > h.outgoing_z_m + tie_m) return h.incoming_slope;
  return side > 0 ? h.outgoing_slope : h.incoming_slope;
}

double kinematic_centre_height_m(const JointParams& joint, const WheelParams& wheel, double wheel_x_m) {
  return KinematicPath(joint, wheel).centre_height_m(wheel_x_m);
}

double kinematic_centre_slope(const JointParams& joint, const WheelParams& wheel, double wheel_x_m, int side) {
  return KinematicPath(joint, wheel).centre_slope(wheel_x_m, side);
}

}  // namespace railjoint
