#include "models/wheel_tread.h"

#include "models/profile_curve.h"

namespace railjoint {

bool has_cylindrical_tread(const WheelParams& wheel) { return wheel.conicity == 0.0 && !wheel.measured_tread; }

double tread_radius_m(const WheelParams& wheel, double y_m) {
  if (wheel.measured_tread) return wheel.measured_tread->value_m(y_m - wheel.lateral_m);
  return wheel.radius_m - wheel.conicity * (y_m - wheel.lateral_m);
}

double tread_radius_slope(const WheelParams& wheel, double y_m) {
  if (wheel.measured_tread) return wheel.measured_tread->slope(y_m - wheel.lateral_m);
  return -wheel.conicity;
}

}  // namespace railjoint
