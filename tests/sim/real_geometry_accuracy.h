#pragma once
// The simulated jump on seeded random crossings of real wheel and rail
// geometry (crowned heads, conical treads, curved dips, end-post gaps under
// any wheel) against the independent reference of the general model
// (tests/models/general_geometry_reference.h), grouped as the README's
// accuracy table. A fast subset runs in the default suite, the study (label
// "study") on a seed never looked at while developing.

#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "models/parameter_checks.h"
#include "sim/setting_checks.h"
#include "sim/simulate_crossing.h"
#include "support/input_error.h"
#include "tests/models/general_geometry_reference.h"
#include "tests/sim/random_scene_accuracy.h"

namespace railjoint::testing_reference {

/// `count` crossings from `seed`, in turn: crowned head (rho 0.2-1 m),
/// conical tread (|kappa| <= 0.05), both, a curved dip (quadratic or cosine
/// over 0.1-0.5 m, crown and cone or not), a gap of 0-8 mm under any wheel
/// (crown and cone or not). theta 15-90 deg, beta 0.005-0.05, v 10-50 m/s,
/// R 437.5-487.5 mm, thin discs and cylinders of 2-30 mm, the wheel 1 mm
/// inside the head's edge as in random_scenes.h.
inline std::vector<RandomCrossing> real_geometry_crossings(int count, std::uint64_t seed) {
  PortableUniform uniform(seed);
  const char* groups[] = {"crown", "cone", "crown+cone", "dip shape", "gap, any wheel"};
  std::vector<RandomCrossing> out;
  for (int i = 0; i < count; ++i) {
    const int g = i % 5;
    RandomCrossing c;
    c.wheel.mass_kg = 750.0;
    draw_inclined_crossing(uniform, c);
    const bool crown = g == 0 || g == 2 || (g >= 3 && uniform(0, 1) < 0.5);
    const bool cone = g == 1 || g == 2 || (g >= 3 && uniform(0, 1) < 0.5);
    if (crown) c.joint.crown_radius_m = uniform(0.2, 1.0);
    if (cone) c.wheel.conicity = uniform(-0.05, 0.05);
    if (g == 3) {
      c.joint.dip_shape = uniform(0, 1) < 0.5 ? DipShape::quadratic : DipShape::cosine;
      c.joint.dip_length_m = uniform(0.1, 0.5);
    }
    if (g == 4) c.joint.gap_m = uniform(0.0, 0.008);
    c.name = std::string(groups[g]) + "#" + std::to_string(i);
    out.push_back(c);
  }
  return out;
}

/// `count` crossings on the 60E1 head (its whole 72 mm top, b_t = 36 mm)
/// under a conical tread (|kappa| <= 0.05, a cylinder in one of four), a thin
/// disc or a wheel 2-100 mm wide, the other ranges as above.
inline std::vector<RandomCrossing> rail_60e1_crossings(int count, std::uint64_t seed) {
  PortableUniform uniform(seed);
  std::vector<RandomCrossing> out;
  for (int i = 0; i < count; ++i) {
    RandomCrossing c;
    c.joint.rail_profile = RailProfile::en_60e1;
    c.joint.half_width_m = 0.036;
    c.joint.theta_rad = uniform(15.0, 90.0) * std::numbers::pi / 180.0;
    c.joint.beta_rad = uniform(0.005, 0.05);
    c.wheel.mass_kg = 750.0;
    c.wheel.radius_m = uniform(0.4375, 0.4875);
    c.wheel.speed_m_per_s = uniform(10.0, 50.0);
    c.wheel.width_m = uniform(0, 1) < 0.5 ? 0.0 : uniform(0.002, 0.100);
    c.wheel.lateral_m = uniform(-0.035, 0.035);
    if (uniform(0, 1) < 0.75) c.wheel.conicity = uniform(-0.05, 0.05);
    c.name = "60E1#" + std::to_string(i);
    out.push_back(c);
  }
  return out;
}

/// The reference's geometry of a crossing, for the wheel as simulated
/// (simulated_wheel_of: on analytic rail tops a thin disc is simulated as a
/// disc; on the thesis's meshes by its stand-in); its half length is the
/// caller's, the rails the run had.
inline reference::Geometry reference_geometry_of(const RandomCrossing& c, const SimSettings& settings) {
  reference::Geometry g;
  g.theta_rad = c.joint.theta_rad;
  g.beta_rad = c.joint.beta_rad;
  g.half_width_m = c.joint.half_width_m;
  g.gap_m = c.joint.gap_m;
  g.crown_radius_m = c.joint.crown_radius_m;
  g.head_60e1 = c.joint.rail_profile == RailProfile::en_60e1;
  g.dip_shape = static_cast<int>(c.joint.dip_shape);
  g.dip_length_m = c.joint.dip_length_m;
  const WheelParams simulated = simulated_wheel_of(c.joint, c.wheel, settings);
  g.radius_m = simulated.radius_m;
  g.width_m = simulated.width_m;
  g.lateral_m = simulated.lateral_m;
  g.conicity = simulated.conicity;
  return g;
}

/// One crossing simulated with `settings` and its reference jump.
inline AccuracyRow run_real_geometry_case(const RandomCrossing& c, const SimSettings& settings) {
  AccuracyRow row;
  row.crossing = c;
  row.group = c.name.substr(0, c.name.find('#'));
  reference::Geometry g = reference_geometry_of(c, settings);
  try {
    const SimulationResult r = simulate_crossing(c.joint, c.wheel, settings);
    // The rails as the run had them (the length it derived).
    g.half_length_m = r.model->joint.length_m / 2.0;
    const reference::Jump ref = reference::crossing(g);
    row.exact_Ns = c.wheel.mass_kg * c.wheel.speed_m_per_s * static_cast<double>(ref.jump_per_Mv());
    record_run(row, r);
  } catch (const InputError& e) {
    row.refused = true;
    row.refusal = e.what();
  }
  return row;
}

/// The issue's targets: no refusal, every vouched run within 1e-4 of the
/// reference, 90 % of them within 1e-6.
inline void expect_real_geometry_accurate(const std::vector<AccuracyRow>& rows) {
  std::vector<double> errors;
  for (const AccuracyRow& row : rows) {
    EXPECT_FALSE(row.refused) << row.crossing.name << ": " << row.refusal;
    if (row.refused || !row.vouched) continue;
    errors.push_back(std::abs(row.relative_error));
    EXPECT_LE(std::abs(row.relative_error), 1e-4) << row.crossing.name;
  }
  ASSERT_FALSE(errors.empty());
  EXPECT_LE(quantile(errors, 0.9), 1e-6);
  print_accuracy_table(rows);
}

/// real_geometry_crossings(count, seed) and rail_60e1_crossings(count_60e1,
/// seed), run and held to those targets (the study and its fast subset).
inline void expect_real_geometry_crossings_accurate(int count, int count_60e1, std::uint64_t seed) {
  std::vector<AccuracyRow> rows;
  std::vector<RandomCrossing> crossings = real_geometry_crossings(count, seed);
  for (const RandomCrossing& c : rail_60e1_crossings(count_60e1, seed)) crossings.push_back(c);
  for (const RandomCrossing& c : crossings) rows.push_back(run_real_geometry_case(c, SimSettings{}));
  expect_real_geometry_accurate(rows);
}

}  // namespace railjoint::testing_reference
