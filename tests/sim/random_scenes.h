#pragma once
// Seeded random crossings over the whole parameter range, for judging the
// simulation on scenes nobody tuned it to (never on the validation set
// alone). Ranges: the thesis's table 4.1 (v 10-50 m/s, theta up to 90 deg,
// beta up to 0.05 rad, |y_w| up to b_t = 20 mm, R = 475 mm with wear down to
// 437.5 mm and new wheels up to 487.5 mm), widened below to theta 15 deg;
// steps up and down to 10 mm at up to 80 m/s on wheels of 440-540 mm;
// finite-width cylinders of 2-30 mm; end-post gaps of up to 3 mm.

#include <cstdint>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "models/parameters.h"

namespace railjoint::testing_reference {

struct RandomCrossing {
  std::string name;
  JointParams joint;
  WheelParams wheel;
};

/// Uniform draws in [lo, hi) from mt19937_64, the same on every machine: 53
/// random bits of the raw output -> [0, 1) (std::uniform_real_distribution
/// is not specified bit for bit).
class PortableUniform {
 public:
  explicit PortableUniform(std::uint64_t seed) : engine_(seed) {}
  double operator()(double lo, double hi) {
    const double unit = static_cast<double>(engine_() >> 11) * 0x1.0p-53;
    return lo + (hi - lo) * unit;
  }

 private:
  std::mt19937_64 engine_;
};

/// The draws an inclined random crossing of every family makes, in this
/// order (a seed's crossings depend on it): theta 15-90 deg, beta
/// 0.005-0.05, R 437.5-487.5 mm, v 10-50 m/s, a thin disc or a cylinder of
/// 2-30 mm, y_w keeping a thin disc's stand-in (and a cylinder's rim) 1 mm
/// inside the rail head.
inline void draw_inclined_crossing(PortableUniform& uniform, RandomCrossing& c) {
  c.joint.theta_rad = uniform(15.0, 90.0) * std::numbers::pi / 180.0;
  c.joint.beta_rad = uniform(0.005, 0.05);
  c.wheel.radius_m = uniform(0.4375, 0.4875);
  c.wheel.speed_m_per_s = uniform(10.0, 50.0);
  c.wheel.width_m = uniform(0, 1) < 0.5 ? 0.0 : uniform(0.002, 0.030);
  const double reach = c.joint.half_width_m - 0.001;
  c.wheel.lateral_m = uniform(-reach, reach);
}

/// `count` crossings from `seed`; every third one a step joint. The same
/// seed gives the same crossings on every machine (mt19937_64 is specified
/// bit for bit; the draws use only its raw output).
inline std::vector<RandomCrossing> random_crossings(int count, std::uint64_t seed) {
  PortableUniform uniform(seed);
  std::vector<RandomCrossing> out;
  for (int i = 0; i < count; ++i) {
    RandomCrossing c;
    c.wheel.mass_kg = 750.0;
    if (i % 3 == 2) {
      c.joint.kind = JointKind::step;
      const double height = uniform(0.0005, 0.010);
      c.joint.step_height_m = uniform(0, 1) < 0.5 ? height : -height;
      c.wheel.radius_m = uniform(0.44, 0.54);
      c.wheel.speed_m_per_s = uniform(10.0, 80.0);
      c.wheel.lateral_m = 0.0;
      c.name = std::string(height == c.joint.step_height_m ? "step_up_" : "step_down_") + std::to_string(i);
    } else {
      c.joint.kind = JointKind::inclined;
      draw_inclined_crossing(uniform, c);
      c.name = std::string(c.wheel.width_m > 0 ? "cylinder_" : "disc_") + std::to_string(i);
    }
    if (uniform(0, 1) < 0.25) c.joint.gap_m = uniform(0.0, 0.003);
    out.push_back(c);
  }
  return out;
}

/// random_crossings(count, seed) below the thesis's speeds: each speed
/// mapped linearly onto 2-10 m/s (10-50 m/s for inclined joints, 10-80 m/s
/// for steps), where a pivot before a landing lasts tens of milliseconds.
inline std::vector<RandomCrossing> low_speed_crossings(int count, std::uint64_t seed) {
  std::vector<RandomCrossing> out = random_crossings(count, seed);
  for (RandomCrossing& c : out) {
    const double top = c.joint.kind == JointKind::step ? 80.0 : 50.0;
    c.wheel.speed_m_per_s = 2.0 + 8.0 * (c.wheel.speed_m_per_s - 10.0) / (top - 10.0);
  }
  return out;
}

}  // namespace railjoint::testing_reference
