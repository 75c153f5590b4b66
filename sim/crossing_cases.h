#pragma once
// Named crossings built in code, for the tests and the inertia study (the
// validation set is scenes/validation/*.toml). Thesis parameters: R = 475 mm,
// M = 750 kg, b_t = 20 mm, beta = 0.03 rad, v = 50 m/s unless the arguments
// say otherwise. y_t = R sin(beta/2) tan(theta) = 4.11 / 7.12 / 12.34 mm at
// theta = 30 / 45 / 60 deg: y_w = 2 mm is scenario 1 at all three, 15 mm
// scenario 2.

#include <numbers>
#include <string>
#include <vector>

#include "models/parameters.h"

namespace railjoint {

struct CrossingCase {
  std::string name;
  JointParams joint;
  WheelParams wheel;
};

inline CrossingCase inclined_crossing(std::string name, double theta_deg, double lateral_m, double speed_m_per_s = 50.0,
                                      double width_m = 0.0) {
  CrossingCase c;
  c.name = std::move(name);
  c.joint.kind = JointKind::inclined;
  c.joint.theta_rad = theta_deg * std::numbers::pi / 180.0;
  c.joint.beta_rad = 0.03;
  c.wheel.lateral_m = lateral_m;
  c.wheel.speed_m_per_s = speed_m_per_s;
  c.wheel.width_m = width_m;
  return c;
}

inline CrossingCase step_crossing(std::string name, double step_height_m, double speed_m_per_s = 50.0) {
  CrossingCase c;
  c.name = std::move(name);
  c.joint.kind = JointKind::step;
  c.joint.step_height_m = step_height_m;
  c.wheel.lateral_m = 0.0;
  c.wheel.speed_m_per_s = speed_m_per_s;
  return c;
}

}  // namespace railjoint
