#include "models/dip_profile.h"

#include <cassert>
#include <cmath>

namespace railjoint {

namespace {
// Incoming rail falls towards the V bottom, outgoing rises from it.
double side_sign(int rail) {
  assert(rail == 0 || rail == 1);
  return rail == 0 ? -1.0 : 1.0;
}
}  // namespace

double dip_height_m(const JointParams& joint, int rail, double x_m) {
  return side_sign(rail) * std::tan(joint.beta_rad / 2.0) * x_m;
}

double dip_slope(const JointParams& joint, int rail, double /*x_m*/) {
  return side_sign(rail) * std::tan(joint.beta_rad / 2.0);
}

int dip_pieces_along_x(const JointParams& /*joint*/) { return 1; }

}  // namespace railjoint
