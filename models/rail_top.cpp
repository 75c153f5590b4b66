#include "models/rail_top.h"

#include <cassert>
#include <cmath>
#include <limits>

#include "models/dip_profile.h"
#include "models/inclined_joint.h"
#include "models/rail_head.h"

namespace railjoint {

double cut_x_m(const JointParams& joint, double y_m, int rail) {
  assert(rail == 0 || rail == 1);
  const double side = rail == 0 ? -1.0 : 1.0;
  if (joint.kind == JointKind::step) return side * gap_half_shift_m(joint);
  return cut_x_m(joint.theta_rad, y_m) + side * gap_half_shift_m(joint);
}

double rail_surface_height_m(const JointParams& joint, int rail, double x_m) {
  if (joint.kind == JointKind::step) return rail == 0 ? 0.0 : joint.step_height_m;
  return dip_height_m(joint, rail, x_m);
}

double rail_surface_slope(const JointParams& joint, int rail, double x_m) {
  if (joint.kind == JointKind::step) return 0.0;
  return dip_slope(joint, rail, x_m);
}

double rail_top_height_m(const JointParams& joint, double x_m, double y_m) {
  const double half_length = joint.length_m / 2.0;
  if (std::abs(y_m) <= joint.half_width_m) {
    const double crown_m = head_top_height_m(joint, y_m);
    if (x_m >= -half_length && x_m <= cut_x_m(joint, y_m, 0)) return crown_m + rail_surface_height_m(joint, 0, x_m);
    if (x_m >= cut_x_m(joint, y_m, 1) && x_m <= half_length) return crown_m + rail_surface_height_m(joint, 1, x_m);
  }
  return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace railjoint
