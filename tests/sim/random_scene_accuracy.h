#pragma once
// The simulated jump on seeded random crossings against the exact reference
// (exact_jump_reference.h), grouped by what happens at the joint, with the
// median, 90th percentile and maximum of |relative error| per group: the
// figures the README's random-scene table and the targets speak of.
// Shared by the fast subset (default suite) and the full study (label study).

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "models/input_error.h"
#include "sim/simulate_crossing.h"
#include "tests/sim/exact_jump_reference.h"
#include "tests/sim/random_scenes.h"

namespace railjoint::testing_reference {

struct AccuracyRow {
  RandomCrossing crossing;
  std::string group;
  bool refused = false;       ///< simulate_crossing refused the scene (InputError)
  std::string refusal;
  double exact_Ns = 0.0;
  double simulated_Ns = 0.0;
  double relative_error = 0.0;  ///< (simulated - exact) / exact
  bool vouched = false;         ///< the run's own verdict was "ok"
  std::string verdict_reason;
  double wall_s = 0.0;
};

inline std::string group_of(const RandomCrossing& c, const ExactJump& exact) {
  if (c.joint.kind == JointKind::step) return c.joint.step_height_m > 0 ? "step up" : "step down";
  const std::string wheel = c.wheel.width_m > 0 ? "cylinder" : "thin disc";
  if (exact.on_landing) return wheel + ", step-down side";
  if (std::abs(exact.slope_after - std::tan(c.joint.beta_rad / 2.0)) < 1e-12) return wheel + ", scenario 1";
  return wheel + ", scenario 2";
}

inline AccuracyRow run_accuracy_case(const RandomCrossing& c, const SimSettings& settings) {
  AccuracyRow row;
  row.crossing = c;
  const ExactJump exact = exact_jump(c.joint, c.wheel);
  row.group = group_of(c, exact);
  row.exact_Ns = exact.jump_Ns;
  try {
    const SimulationResult r = simulate_crossing(c.joint, c.wheel, settings);
    row.simulated_Ns = r.impact_found ? r.impulse_Ns : 0.0;
    row.relative_error = (row.simulated_Ns - row.exact_Ns) / row.exact_Ns;
    row.vouched = r.verdict.ok;
    row.verdict_reason = r.verdict.reason;
    row.wall_s = r.wall_seconds;
  } catch (const InputError& e) {
    row.refused = true;
    row.refusal = e.what();
  }
  return row;
}

struct GroupStats {
  int cases = 0;
  int refused = 0;
  int suspect = 0;               ///< the run said it could not vouch for its number
  double median = 0, p90 = 0, max = 0;  ///< |relative error| over the vouched runs
  double wall_median_s = 0, wall_max_s = 0;
};

inline double quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  // Nearest rank: the smallest value with at least q of the sample at or below it.
  const auto rank = static_cast<std::size_t>(std::ceil(q * static_cast<double>(v.size())));
  return v[std::min(v.size() - 1, rank == 0 ? 0 : rank - 1)];
}

inline std::map<std::string, GroupStats> group_stats(const std::vector<AccuracyRow>& rows) {
  std::map<std::string, std::vector<double>> errors, walls;
  std::map<std::string, GroupStats> stats;
  for (const AccuracyRow& row : rows) {
    for (const std::string& g : {row.group, std::string("all")}) {
      GroupStats& s = stats[g];
      ++s.cases;
      if (row.refused) {
        ++s.refused;
        continue;
      }
      walls[g].push_back(row.wall_s);
      if (!row.vouched) {
        ++s.suspect;
        continue;
      }
      errors[g].push_back(std::abs(row.relative_error));
    }
  }
  for (auto& [g, s] : stats) {
    s.median = quantile(errors[g], 0.5);
    s.p90 = quantile(errors[g], 0.9);
    s.max = quantile(errors[g], 1.0);
    s.wall_median_s = quantile(walls[g], 0.5);
    s.wall_max_s = quantile(walls[g], 1.0);
  }
  return stats;
}

inline void print_accuracy_table(const std::vector<AccuracyRow>& rows) {
  std::printf("| group | cases | refused | suspect | median abs. error | 90th pct | max | median wall [ms] | max wall [ms] |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const auto& [g, s] : group_stats(rows)) {
    std::printf("| %s | %d | %d | %d | %.1e | %.1e | %.1e | %.2f | %.1f |\n", g.c_str(), s.cases, s.refused, s.suspect,
                s.median, s.p90, s.max, 1e3 * s.wall_median_s, 1e3 * s.wall_max_s);
  }
}

inline void print_accuracy_rows(const std::vector<AccuracyRow>& rows) {
  for (const AccuracyRow& row : rows) {
    const auto& c = row.crossing;
    std::printf("%-14s %-28s theta %5.1f deg beta %.4f y %+8.5f m w %.4f m R %.4f v %5.1f u0 %+.4f gap %.4f: ", c.name.c_str(),
                row.group.c_str(), c.joint.theta_rad * 180.0 / 3.14159265358979, c.joint.beta_rad, c.wheel.lateral_m,
                c.wheel.width_m, c.wheel.radius_m, c.wheel.speed_m_per_s,
                c.joint.kind == JointKind::step ? c.joint.step_height_m : 0.0, c.joint.gap_m);
    if (row.refused) {
      std::printf("refused (%s)\n", row.refusal.c_str());
    } else {
      std::printf("exact %.3f N s, simulated %.3f N s, error %+.2e, %s%s%s, %.2f ms\n", row.exact_Ns, row.simulated_Ns,
                  row.relative_error, row.vouched ? "ok" : "suspect", row.vouched ? "" : ": ",
                  row.verdict_reason.c_str(), 1e3 * row.wall_s);
    }
  }
}

/// Prints the rows and the table, then holds every run that vouches for its
/// number to the bound for every realistic scene, 1e-3; a run that
/// cannot vouch (verdict "suspect") must say why.
inline void expect_vouched_runs_accurate(const std::vector<AccuracyRow>& rows) {
  print_accuracy_rows(rows);
  print_accuracy_table(rows);
  for (const AccuracyRow& row : rows) {
    if (row.refused) continue;
    if (row.vouched) {
      EXPECT_LE(std::abs(row.relative_error), 1e-3) << row.crossing.name;
    } else {
      EXPECT_FALSE(row.verdict_reason.empty()) << row.crossing.name;
    }
  }
}

}  // namespace railjoint::testing_reference
