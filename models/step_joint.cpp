#include "models/step_joint.h"

#include <cassert>
#include <cmath>

namespace railjoint {

double step_edge_distance_large_R_m(double radius_m, double step_height_m) {
  assert(step_height_m >= 0.0 && step_height_m < radius_m);
  return std::sqrt(2.0 * radius_m * step_height_m);
}

double step_zdot_after_thesis(double radius_m, double step_height_m, double speed_m_per_s) {
  const double R = radius_m;
  const double u0 = step_height_m;
  // Eq. 3.6 is only defined while R^2 > 2 R u0 (u0 < R/2); beyond it the
  // printed form has no real value and the caller gets NaN, not a made-up number.
  return speed_m_per_s * std::sqrt(2.0 * R * u0) / std::sqrt(R * R - 2.0 * R * u0);
}

}  // namespace railjoint
