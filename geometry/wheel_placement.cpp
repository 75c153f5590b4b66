#include "geometry/wheel_placement.h"

#include <cmath>

#include "models/rail_top.h"

namespace railjoint {

Eigen::Vector3d wheel_centre_on_incoming_rail_m(const JointParams& joint, const WheelParams& wheel,
                                                double contact_x_m) {
  const double m = rail_surface_slope(joint, 0, contact_x_m);
  const Eigen::Vector3d contact(contact_x_m, wheel.lateral_m, rail_surface_height_m(joint, 0, contact_x_m));
  return contact + wheel.radius_m * Eigen::Vector3d(-m, 0.0, 1.0) / std::sqrt(1.0 + m * m);
}

}  // namespace railjoint
