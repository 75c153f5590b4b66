#include "models/rail_head.h"

#include <cmath>

namespace railjoint {

bool has_flat_head(const JointParams& joint) { return joint.crown_radius_m == 0.0; }

double head_top_height_m(const JointParams& joint, double y_m) {
  if (has_flat_head(joint)) return 0.0;
  const double rho = joint.crown_radius_m;
  // -y^2 / (rho + sqrt(rho^2 - y^2)): the same value without the cancellation
  // of sqrt(rho^2 - y^2) - rho near the crest.
  return -y_m * y_m / (rho + std::sqrt((rho - y_m) * (rho + y_m)));
}

double head_top_slope(const JointParams& joint, double y_m) {
  if (has_flat_head(joint)) return 0.0;
  const double rho = joint.crown_radius_m;
  return -y_m / std::sqrt((rho - y_m) * (rho + y_m));
}

}  // namespace railjoint
