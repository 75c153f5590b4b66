#pragma once
// The named crossings the simulation is validated on (the accuracy table of
// the report, the regression tests and the benchmarks share them rather than
// each building its own). Thesis parameters: R = 475 mm, M = 750 kg,
// b_t = 20 mm, beta = 0.03 rad, v = 50 m/s unless the name says otherwise.

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

/// y_t = R sin(beta/2) tan(theta) = 4.11 / 7.12 / 12.34 mm at theta = 30 / 45 / 60 deg:
/// y_w = 2 mm is scenario 1 at all three, y_w = 15 mm scenario 2.
inline std::vector<CrossingCase> validation_crossings() {
  return {
      inclined_crossing("square_joint", 90.0, 0.015),
      inclined_crossing("scenario1_theta30", 30.0, 0.002),
      inclined_crossing("scenario1_theta45", 45.0, 0.002),
      inclined_crossing("scenario1_theta60", 60.0, 0.002),
      inclined_crossing("scenario1_theta30_near_transition", 30.0, 0.003),
      inclined_crossing("scenario2_theta30", 30.0, 0.015),
      inclined_crossing("scenario2_theta45", 45.0, 0.015),
      inclined_crossing("scenario2_theta60", 60.0, 0.015),
      inclined_crossing("scenario2_theta30_v10", 30.0, 0.015, 10.0),
      inclined_crossing("cylinder_10mm_theta30", 30.0, 0.015, 50.0, 0.010),
      inclined_crossing("cylinder_30mm_line_contact", 30.0, 0.015, 50.0, 0.030),
      inclined_crossing("step_down_theta30", 30.0, -0.015),
      step_crossing("step_up_1mm", 0.001),
      step_crossing("step_up_1mm_v10", 0.001, 10.0),
  };
}

}  // namespace railjoint
