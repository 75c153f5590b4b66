#include "models/parameter_checks.h"

#include <cmath>
#include <numbers>
#include <string>

#include "models/parameter_error.h"

namespace railjoint {

namespace {
std::string mm(double metres) { return std::to_string(metres * 1e3) + " mm"; }
}  // namespace

void check_parameters(const JointParams& joint, const WheelParams& wheel) {
  if (!(joint.theta_rad > 0.0 && joint.theta_rad <= std::numbers::pi / 2.0)) {
    throw ParameterError("joint.theta_deg", "junction angle must be in (0, 90] deg");
  }
  if (!(joint.beta_rad >= 0.0 && joint.beta_rad < std::numbers::pi / 2.0)) {
    throw ParameterError("joint.beta", "dip angle must be in [0, pi/2) rad");
  }
  if (!(joint.half_width_m > 0.0)) throw ParameterError("joint.half_width", "rail-head half-width must be > 0 m");
  if (!(wheel.radius_m > 0.0)) throw ParameterError("wheel.radius", "wheel radius must be > 0 m");
  if (!(wheel.mass_kg > 0.0)) throw ParameterError("wheel.mass", "wheel mass must be > 0 kg");
  if (!(wheel.speed_m_per_s > 0.0)) throw ParameterError("wheel.speed", "speed must be > 0 m/s");
  if (!(wheel.width_m >= 0.0)) throw ParameterError("wheel.width", "wheel width must be >= 0 m (0 = thin disc)");
  if (!(std::abs(wheel.lateral_m) <= joint.half_width_m)) {
    throw ParameterError("wheel.y", "lateral position must lie on the rail head, |y| <= joint.half_width = " +
                                        mm(joint.half_width_m) + ", got " + mm(wheel.lateral_m));
  }
  if (joint.kind == JointKind::step && !(std::abs(joint.step_height_m) < wheel.radius_m)) {
    throw ParameterError("joint.step_height", "step height must satisfy |u0| < wheel.radius = " +
                                                  std::to_string(wheel.radius_m) + " m");
  }
}

}  // namespace railjoint
