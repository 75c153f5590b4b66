#pragma once
// The simulated jump on seeded random crossings against the exact reference
// (exact_jump_reference.h), grouped by what happens at the joint, with the
// median, 90th percentile and maximum of |relative error| per group: the
// figures the README's random-scene table and the targets speak of.
// Shared by the fast subset (default suite) and the full study (label study).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "sim/crossing_model.h"
#include "sim/setting_checks.h"
#include "sim/simulate_crossing.h"
#include "support/input_error.h"
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

/// The run's jump, its error against row.exact_Ns (set first), verdict and wall time.
inline void record_run(AccuracyRow& row, const SimulationResult& r) {
  row.simulated_Ns = r.impact_found() ? r.impulse_Ns() : 0.0;
  row.relative_error = (row.simulated_Ns - row.exact_Ns) / row.exact_Ns;
  row.vouched = r.verdict.ok;
  row.verdict_reason = r.verdict.reason;
  row.wall_s = r.wall_seconds;
}

inline AccuracyRow run_accuracy_case(const RandomCrossing& c, const SimSettings& settings) {
  AccuracyRow row;
  row.crossing = c;
  const ExactJump exact = exact_jump(c.joint, c.wheel);
  row.group = group_of(c, exact);
  row.exact_Ns = exact.jump_Ns;
  try {
    record_run(row, simulate_crossing(c.joint, c.wheel, settings));
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

/// Inertial mode, service load (sim defaults), on the scenes whose wheel
/// strikes the outgoing rail's corner (scenario 2, step up): the strike's
/// jump against the kinematic reference (a rigid strike is the same impulse
/// whatever the load) and, where the load cannot hold the wheel on the
/// corner (v > v_c(alpha)), the landing after the flight against the
/// ballistic reference (exact_landing_after_strike). Rails as long as the
/// flight needs (rail_length_needed_m).
struct LandingRow {
  RandomCrossing crossing;
  bool refused = false;
  std::string refusal;
  bool flies = false;                ///< v > v_c at the struck corner
  double strike_error = 0.0;         ///< (simulated - exact) / exact, the joint's jump
  double landing_error = 0.0;        ///< the landing's jump
  double exact_landing_Ns = 0.0;
  double simulated_landing_Ns = 0.0;
  double landing_x_error_m = 0.0;    ///< simulated - exact landing position of the centre
  bool vouched = false;
  std::string verdict_reason;
  double wall_s = 0.0;
};

inline LandingRow run_landing_case(const RandomCrossing& c) {
  LandingRow row;
  row.crossing = c;
  SimSettings settings;
  settings.make_inertial();
  const double load_N = settings.inertial()->wheel_load_N + c.wheel.mass_kg * kStandardGravity_m_per_s2;
  const WheelParams simulated = wheel_as_simulated(c.wheel, settings);
  const WheelSpan span = c.wheel.width_m > 0 ? WheelSpan{c.wheel.lateral_m - 0.5 * c.wheel.width_m,
                                                         c.wheel.lateral_m + 0.5 * c.wheel.width_m}
                                             : WheelSpan{c.wheel.lateral_m, c.wheel.lateral_m};
  const ExactJump exact = exact_jump(c.joint, c.wheel, span);
  // The radius to the struck corner leans back by alpha: sin(alpha) = (p_x - x*) / R.
  const double sin_alpha = (exact.struck_x_m - exact.impact_x_m) / c.wheel.radius_m;
  const double cos_alpha = std::sqrt(1.0 - sin_alpha * sin_alpha);
  const double v_c = std::sqrt(load_N * c.wheel.radius_m * cos_alpha * cos_alpha * cos_alpha / c.wheel.mass_kg);
  row.flies = c.wheel.speed_m_per_s > v_c;
  try {
    JointParams joint = c.joint;
    joint.length_m = std::max(joint.length_m, rail_length_needed_m(joint, c.wheel, settings));
    const SimulationResult r = simulate_crossing(joint, c.wheel, settings);
    row.wall_s = r.wall_seconds;
    row.vouched = r.verdict.ok;
    row.verdict_reason = r.verdict.reason;
    row.strike_error = r.impact_found() ? (r.impulse_Ns() - exact.jump_Ns) / exact.jump_Ns : -1.0;
    if (row.flies) {
      const ExactLanding landing = exact_landing_after_strike(c.joint, c.wheel, span, load_N);
      row.exact_landing_Ns = landing.jump_Ns;
      row.simulated_landing_Ns = r.second_impact ? r.second_impact->impulse_Ns : 0.0;
      row.landing_error = (row.simulated_landing_Ns - landing.jump_Ns) / landing.jump_Ns;
      const auto& impacts = r.trajectory.impacts;
      const int j = r.inertial()->joint_impact_index;
      if (j >= 0 && static_cast<std::size_t>(j + 1) < impacts.size()) {
        row.landing_x_error_m = impacts[static_cast<std::size_t>(j + 1)].wheel_x_m - landing.landing_x_m;
      }
    }
    (void)simulated;
  } catch (const InputError& e) {
    row.refused = true;
    row.refusal = e.what();
  }
  return row;
}

/// Prints every row and the median / 90th percentile / max of the strike's
/// and the landing's |error| over the vouched runs, and holds both to 1e-3.
inline void expect_landings_accurate(const std::vector<LandingRow>& rows) {
  std::vector<double> strikes, landings, walls;
  int suspect = 0, refused = 0;
  for (const LandingRow& row : rows) {
    const auto& c = row.crossing;
    std::printf("%-14s theta %5.1f deg y %+8.5f m w %.4f m v %5.1f u0 %+.4f gap %.4f: ", c.name.c_str(),
                c.joint.theta_rad * 180.0 / 3.14159265358979, c.wheel.lateral_m, c.wheel.width_m,
                c.wheel.speed_m_per_s, c.joint.kind == JointKind::step ? c.joint.step_height_m : 0.0, c.joint.gap_m);
    if (row.refused) {
      ++refused;
      std::printf("refused (%s)\n", row.refusal.c_str());
      continue;
    }
    walls.push_back(row.wall_s);
    std::printf("strike %+.2e, %s landing exact %.3f N s simulated %.3f N s error %+.2e at %+.2e m, %s%s, %.2f ms\n",
                row.strike_error, row.flies ? "flies," : "holds on, no", row.exact_landing_Ns, row.simulated_landing_Ns,
                row.landing_error, row.landing_x_error_m, row.vouched ? "ok" : "suspect: ", row.verdict_reason.c_str(),
                1e3 * row.wall_s);
    if (!row.vouched) {
      ++suspect;
      EXPECT_FALSE(row.verdict_reason.empty()) << c.name;
      continue;
    }
    strikes.push_back(std::abs(row.strike_error));
    EXPECT_LE(std::abs(row.strike_error), 1e-3) << c.name;
    if (row.flies) {
      landings.push_back(std::abs(row.landing_error));
      EXPECT_LE(std::abs(row.landing_error), 1e-3) << c.name;
    }
  }
  std::printf("| inertial | cases | refused | suspect | median | 90th pct | max | median wall [ms] | max wall [ms] |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  std::printf("| strike | %zu | %d | %d | %.1e | %.1e | %.1e | %.2f | %.1f |\n", rows.size(), refused, suspect,
              quantile(strikes, 0.5), quantile(strikes, 0.9), quantile(strikes, 1.0), 1e3 * quantile(walls, 0.5),
              1e3 * quantile(walls, 1.0));
  std::printf("| landing after the flight | %zu | | | %.1e | %.1e | %.1e | | |\n", landings.size(), quantile(landings, 0.5),
              quantile(landings, 0.9), quantile(landings, 1.0));
}

/// The random crossings whose wheel strikes the outgoing rail's corner.
inline std::vector<RandomCrossing> strike_crossings(const std::vector<RandomCrossing>& all) {
  std::vector<RandomCrossing> out;
  for (const RandomCrossing& c : all) {
    const ExactJump exact = exact_jump(c.joint, c.wheel);
    const std::string group = group_of(c, exact);
    if (group == "step up" || group.find("scenario 2") != std::string::npos) out.push_back(c);
  }
  return out;
}

/// random_crossings(count, seed) run rigid (and at 2-10 m/s,
/// low_speed_crossings), and its strikes run inertial (the study and its
/// fast subset), each against the exact reference.
inline void expect_random_crossings_accurate(int count, std::uint64_t seed) {
  std::vector<AccuracyRow> rows;
  for (const RandomCrossing& c : random_crossings(count, seed)) rows.push_back(run_accuracy_case(c, SimSettings{}));
  expect_vouched_runs_accurate(rows);
}
inline void expect_low_speed_crossings_accurate(int count, std::uint64_t seed) {
  std::vector<AccuracyRow> rows;
  for (const RandomCrossing& c : low_speed_crossings(count, seed)) rows.push_back(run_accuracy_case(c, SimSettings{}));
  expect_vouched_runs_accurate(rows);
}
/// low_speed_crossings(count, seed) whose jump is a landing after a pivot,
/// run inertial (service load) where the lift-off model (models/liftoff.h)
/// has the load hold the wheel on the pivot: it then follows the kinematic
/// path, and the landing is the exact jump.
inline void expect_low_speed_inertial_landings_accurate(int count, std::uint64_t seed) {
  SimSettings settings;
  settings.make_inertial();
  std::vector<AccuracyRow> rows;
  int lifting_off = 0;
  for (RandomCrossing c : low_speed_crossings(count, seed)) {
    const ExactJump exact = exact_jump(c.joint, c.wheel);
    if (!exact.on_landing) continue;
    c.joint.length_m = std::max(c.joint.length_m, rail_length_needed_m(c.joint, c.wheel, settings));
    AccuracyRow row;
    row.crossing = c;
    row.group = group_of(c, exact);
    row.exact_Ns = exact.jump_Ns;
    const SimulationResult r = simulate_crossing(c.joint, c.wheel, settings);
    if (r.inertial()->liftoff_predicted) {
      ++lifting_off;
      continue;
    }
    record_run(row, r);
    rows.push_back(row);
  }
  std::printf("%d landings left out: the lift-off model has the wheel leave the pivot\n", lifting_off);
  expect_vouched_runs_accurate(rows);
}
inline void expect_random_landings_accurate(int count, std::uint64_t seed) {
  std::vector<LandingRow> rows;
  for (const RandomCrossing& c : strike_crossings(random_crossings(count, seed))) rows.push_back(run_landing_case(c));
  expect_landings_accurate(rows);
}

}  // namespace railjoint::testing_reference
