#include "models/wheel_tread.h"

namespace railjoint {

bool has_cylindrical_tread(const WheelParams& wheel) { return wheel.conicity == 0.0; }

double tread_radius_m(const WheelParams& wheel, double y_m) {
  return wheel.radius_m - wheel.conicity * (y_m - wheel.lateral_m);
}

double tread_radius_slope(const WheelParams& wheel) { return -wheel.conicity; }

}  // namespace railjoint
