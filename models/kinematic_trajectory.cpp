#include "models/kinematic_trajectory.h"

#include <algorithm>

#include "models/finite_width_wheel.h"
#include "models/slice_profile.h"
#include "models/wheel_rail_envelope.h"

namespace railjoint {

namespace {
// Each rail's support of the wheel: the governing slice's profile where one
// slice carries it (the thesis's model), else the envelope over all slices.
struct RailHeights {
  double incoming_z_m, incoming_slope;
  double outgoing_z_m, outgoing_slope;
};

RailHeights rail_heights(const JointParams& joint, const WheelParams& wheel, double wheel_x_m) {
  if (governing_slice_rule_holds(joint, wheel)) {
    const SliceProfile profile = slice_profile(joint, governing_slice_y_m(joint, wheel));
    const SegmentSupport in = segment_support(profile[0], wheel.radius_m, wheel_x_m);
    const SegmentSupport out = segment_support(profile[1], wheel.radius_m, wheel_x_m);
    return {in.centre_z_m, in.slope, out.centre_z_m, out.slope};
  }
  const RailSupport in = rail_support(joint, wheel, 0, wheel_x_m);
  const RailSupport out = rail_support(joint, wheel, 1, wheel_x_m);
  return {in.centre_z_m, in.slope, out.centre_z_m, out.slope};
}
}  // namespace

double kinematic_centre_height_m(const JointParams& joint, const WheelParams& wheel, double wheel_x_m) {
  const RailHeights h = rail_heights(joint, wheel, wheel_x_m);
  return std::max(h.incoming_z_m, h.outgoing_z_m);
}

double kinematic_centre_slope(const JointParams& joint, const WheelParams& wheel, double wheel_x_m, int side) {
  // At a kink the two rails hold the centre equally high; the side asked for
  // decides which one carries it an infinitesimal step away.
  const RailHeights h = rail_heights(joint, wheel, wheel_x_m);
  const double tie_m = 1e-12 * std::max(1.0, wheel.radius_m);
  if (h.outgoing_z_m > h.incoming_z_m + tie_m) return h.outgoing_slope;
  if (h.incoming_z_m > h.outgoing_z_m + tie_m) return h.incoming_slope;
  return side > 0 ? h.outgoing_slope : h.incoming_slope;
}

}  // namespace railjoint
