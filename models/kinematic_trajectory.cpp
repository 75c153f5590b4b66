#include "models/kinematic_trajectory.h"

#include <algorithm>

#include "models/finite_width_wheel.h"
#include "models/slice_profile.h"

namespace railjoint {

namespace {
SliceProfile governing_profile(const JointParams& joint, const WheelParams& wheel) {
  const double y = joint.kind == JointKind::step ? wheel.lateral_m : select_governing_slice(joint, wheel).governing_y_m;
  return slice_profile(joint, y);
}
}  // namespace

double kinematic_centre_height_m(const JointParams& joint, const WheelParams& wheel, double wheel_x_m) {
  return profile_support(governing_profile(joint, wheel), wheel.radius_m, wheel_x_m).centre_z_m;
}

double kinematic_centre_slope(const JointParams& joint, const WheelParams& wheel, double wheel_x_m, int side) {
  // At a kink the two rails hold the centre equally high; the side asked for
  // decides which one carries it an infinitesimal step away.
  const SliceProfile profile = governing_profile(joint, wheel);
  const SegmentSupport in = segment_support(profile[0], wheel.radius_m, wheel_x_m);
  const SegmentSupport out = segment_support(profile[1], wheel.radius_m, wheel_x_m);
  const double tie_m = 1e-12 * std::max(1.0, wheel.radius_m);
  if (out.centre_z_m > in.centre_z_m + tie_m) return out.slope;
  if (in.centre_z_m > out.centre_z_m + tie_m) return in.slope;
  return side > 0 ? out.slope : in.slope;
}

}  // namespace railjoint
