#pragma once
// Inertial rigid runs (service load, horizontal speed held, frictionless,
// plastic) on seeded random crossings of real geometry: the strike at the
// joint against the general model's independent reference jump
// (tests/models/general_geometry_reference.h) and, where the load cannot
// hold the wheel on the outgoing rail, the landing after the flight against
// a ballistic reference written here on the same reference's heights.
//
// The reference path. The wheel is rigid and the horizontal speed v held,
// so while it touches a rail its centre follows that rail's support height
// h_r(x) (the reference's rail_height_m) with zdot = v h_r'(x) and
// zddot = v^2 h_r''(x). The contact can only push, so the wheel stays on
// while the path's downward acceleration, -v^2 h_r'', is at most what the
// load gives, g_W = (W + M g) / M; past that it leaves. Hence:
//  - before the joint: if -v^2 h_0'' > g_W anywhere on the approach the
//    simulation starts on, the wheel leaves the incoming rail before the
//    joint (a curved dip's crest at speed, a pivot over the incoming end
//    into a gap); its first impact is a landing, not the kinematic strike,
//    and the scene is counted but not compared ("leaves before the joint");
//  - otherwise it strikes the outgoing rail where h_1 overtakes h_0 (x*):
//    the jump is M v (h_1'(x*+) - h_0'(x*-)), the reference's crossing();
//  - after it: if -v^2 h_1''(x*+) > g_W it flies on the parabola
//    z(x) = h_1(x*) + s (x - x*) - g_W ((x - x*) / v)^2 / 2, s = h_1'(x*+),
//    until z meets h_1 again at x_L, where it lands plastically (restitution
//    0): jump M (v h_1'(x_L+) - zdot(x_L)). On the thesis's geometry this is
//    exact_landing_after_strike (exact_jump_reference.h).
//
// Numerics: h_r comes from golden-section maxima in long double (good to
// ~1e-19 m), so the second differences at spacing 1e-4 m (1e-5 m within
// 1 mm of x*, where a pivot over the incoming end bends the path at ~1 / R
// over a fraction of a millimetre) carry ~1e-11 / m of noise against the
// 0.1-2 / m that decide; the landing is marched in 0.1 mm and bisected to
// 1e-12 m, and its slope is the reference's one-sided three-point form.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/sim/real_geometry_accuracy.h"

namespace railjoint::testing_reference {

struct RealInertialReference {
  bool leaves_before_joint = false;
  double strike_Ns = 0.0;
  bool flies_after = false;
  double demand_after = 0.0;  ///< -v^2 h_1''(x*+) / g_W: above 1 it flies
  double landing_x_m = 0.0;
  double landing_Ns = 0.0;
};

/// The reference path above for `g` (its half length the run's), wheel mass
/// and speed of `c`, a constant vertical load `load_N` (weight included),
/// the simulation starting `approach_m` before the strike.
inline RealInertialReference real_inertial_reference(const reference::Geometry& g, const RandomCrossing& c,
                                                     double load_N, double approach_m) {
  using reference::Real;
  const Real v = c.wheel.speed_m_per_s;
  const Real M = c.wheel.mass_kg;
  const Real g_W = static_cast<Real>(load_N) / M;
  const auto h = [&](int rail, Real x) { return reference::rail_height_m(g, rail, x); };
  const auto bend = [&](int rail, Real x, Real dx) {  // -h'' (> 0: the path bends down)
    return -(h(rail, x + dx) - 2 * h(rail, x) + h(rail, x - dx)) / (dx * dx);
  };
  const reference::Jump jump = reference::crossing(g);
  const Real x_star = jump.centre_x_m;
  RealInertialReference out;
  out.strike_Ns = static_cast<double>(M * v * jump.jump_per_Mv());
  // Before the joint: 64 points over the approach, 100 over its last millimetre.
  Real demand = 0;
  for (int i = 0; i < 64; ++i) {
    const Real x = x_star - 1e-3L - (static_cast<Real>(approach_m) - 1e-3L) * i / 63;
    demand = std::max(demand, bend(0, x, 1e-4L));
  }
  for (int i = 0; i < 100; ++i) demand = std::max(demand, bend(0, x_star - 2e-5L - 1e-5L * i, 1e-5L));
  out.leaves_before_joint = v * v * demand > g_W;
  if (out.leaves_before_joint) return out;
  // After the strike: the demand where the outgoing path starts.
  out.demand_after = static_cast<double>(v * v * bend(1, x_star + 2e-5L, 1e-5L) / g_W);
  out.flies_after = out.demand_after > 1.0;
  if (!out.flies_after) return out;
  const Real z0 = h(1, x_star);
  const Real s = jump.slope_after;
  const auto above = [&](Real x) {
    const Real t = (x - x_star) / v;
    return z0 + s * (x - x_star) - g_W * t * t / 2 - h(1, x);
  };
  Real lo = x_star + 1e-7L, hi = x_star + 1e-4L;
  while (above(hi) > 0 && hi < x_star + 2) {
    lo = hi;
    hi += 1e-4L;
  }
  for (int i = 0; i < 60 && hi - lo > 1e-12L; ++i) {
    const Real mid = (lo + hi) / 2;
    (above(mid) > 0 ? lo : hi) = mid;
  }
  const Real x_L = hi;
  const Real d = 2e-6L;
  const Real slope_L = (-3 * h(1, x_L) + 4 * h(1, x_L + d) - h(1, x_L + 2 * d)) / (2 * d);
  const Real zdot = v * s - g_W * (x_L - x_star) / v;
  out.landing_x_m = static_cast<double>(x_L);
  out.landing_Ns = static_cast<double>(M * (v * slope_L - zdot));
  return out;
}

struct RealInertialRow {
  RandomCrossing crossing;
  std::string group;
  bool refused = false;
  std::string refusal;
  RealInertialReference reference;
  double strike_error = 0.0;   ///< (simulated - reference) / reference
  double landing_error = 0.0;
  double landing_x_error_m = 0.0;
  bool vouched = false;
  std::string verdict_reason;
  double wall_s = 0.0;
};

inline RealInertialRow run_real_inertial_case(const RandomCrossing& c) {
  RealInertialRow row;
  row.crossing = c;
  row.group = c.name.substr(0, c.name.find('#'));
  SimSettings settings;
  settings.make_inertial();
  const double load_N = settings.inertial()->wheel_load_N + c.wheel.mass_kg * kStandardGravity_m_per_s2;
  try {
    JointParams joint = c.joint;
    joint.length_m = std::max(joint.length_m, rail_length_needed_m(joint, c.wheel, settings));
    const SimulationResult r = simulate_crossing(joint, c.wheel, settings);
    reference::Geometry g = reference_geometry_of(c, settings);
    g.half_length_m = r.model->joint.length_m / 2.0;
    row.reference = real_inertial_reference(g, c, load_N, settings.approach_distance_m);
    row.wall_s = r.wall_seconds;
    row.vouched = r.verdict.ok;
    row.verdict_reason = r.verdict.reason;
    row.strike_error = r.impact_found() ? (r.impulse_Ns() - row.reference.strike_Ns) / row.reference.strike_Ns : -1.0;
    if (row.reference.flies_after) {
      const double simulated = r.second_impact ? r.second_impact->impulse_Ns : 0.0;
      row.landing_error = (simulated - row.reference.landing_Ns) / row.reference.landing_Ns;
      const auto& impacts = r.trajectory.impacts;
      const int j = r.inertial()->joint_impact_index;
      if (j >= 0 && static_cast<std::size_t>(j + 1) < impacts.size()) {
        row.landing_x_error_m = impacts[static_cast<std::size_t>(j + 1)].wheel_x_m - row.reference.landing_x_m;
      }
    }
  } catch (const InputError& e) {
    row.refused = true;
    row.refusal = e.what();
  }
  return row;
}

/// Prints every row and, per group, the median / 90th percentile / max of
/// |strike error| and |landing error| over the vouched runs; holds strikes
/// to the 1e-4 and landings to the thesis-geometry table's 1e-3.
inline void expect_real_inertial_accurate(const std::vector<RealInertialRow>& rows) {
  struct Stats {
    int cases = 0, refused = 0, leaves = 0, suspect = 0;
    std::vector<double> strikes, landings, walls;
  };
  std::map<std::string, Stats> groups;
  for (const RealInertialRow& row : rows) {
    const auto& c = row.crossing;
    std::printf("%-16s theta %5.1f deg y %+8.5f m w %.4f m v %5.1f: ", c.name.c_str(),
                c.joint.theta_rad * 180.0 / 3.14159265358979, c.wheel.lateral_m, c.wheel.width_m,
                c.wheel.speed_m_per_s);
    for (const std::string& name : {row.group, std::string("all")}) {
      Stats& s = groups[name];
      ++s.cases;
      if (row.refused) {
        ++s.refused;
      } else if (row.reference.leaves_before_joint) {
        ++s.leaves;
      } else if (!row.vouched) {
        ++s.suspect;
      } else {
        s.walls.push_back(row.wall_s);
        s.strikes.push_back(std::abs(row.strike_error));
        if (row.reference.flies_after) s.landings.push_back(std::abs(row.landing_error));
      }
    }
    if (row.refused) {
      std::printf("refused (%s)\n", row.refusal.c_str());
      ADD_FAILURE() << c.name << " refused: " << row.refusal;
      continue;
    }
    if (row.reference.leaves_before_joint) {
      std::printf("leaves the incoming rail before the joint (not compared)\n");
      continue;
    }
    std::printf("strike %+.2e, demand %.4f g, %s landing %.3f N s error %+.2e at %+.2e m, %s%s, %.2f ms\n", row.strike_error,
                row.reference.demand_after, row.reference.flies_after ? "flies," : "holds on, no", row.reference.landing_Ns, row.landing_error,
                row.landing_x_error_m, row.vouched ? "ok" : "suspect: ", row.verdict_reason.c_str(), 1e3 * row.wall_s);
    if (!row.vouched) {
      EXPECT_FALSE(row.verdict_reason.empty()) << c.name;
      continue;
    }
    EXPECT_LE(std::abs(row.strike_error), 1e-4) << c.name;
    if (row.reference.flies_after) {
      EXPECT_LE(std::abs(row.landing_error), 1e-3) << c.name;
    }
  }
  std::printf("| inertial, real geometry | cases | leaves before | refused | suspect | strike median | 90th pct | max "
              "| landings | landing median | 90th pct | max | median wall [ms] |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const auto& [name, s] : groups) {
    std::printf("| %s | %d | %d | %d | %d | %.1e | %.1e | %.1e | %zu | %.1e | %.1e | %.1e | %.2f |\n", name.c_str(),
                s.cases, s.leaves, s.refused, s.suspect, quantile(s.strikes, 0.5), quantile(s.strikes, 0.9),
                quantile(s.strikes, 1.0), s.landings.size(), quantile(s.landings, 0.5), quantile(s.landings, 0.9),
                quantile(s.landings, 1.0), 1e3 * quantile(s.walls, 0.5));
  }
}

/// real_geometry_crossings(count, seed) and rail_60e1_crossings(count_60e1,
/// seed) run inertial and held to those bounds (the study and its fast subset).
inline void expect_real_inertial_crossings_accurate(int count, int count_60e1, std::uint64_t seed) {
  std::vector<RealInertialRow> rows;
  std::vector<RandomCrossing> crossings = real_geometry_crossings(count, seed);
  for (const RandomCrossing& c : rail_60e1_crossings(count_60e1, seed)) crossings.push_back(c);
  for (const RandomCrossing& c : crossings) rows.push_back(run_real_inertial_case(c));
  expect_real_inertial_accurate(rows);
}

}  // namespace railjoint::testing_reference
