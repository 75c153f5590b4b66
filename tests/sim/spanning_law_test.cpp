// What the merged-patch law's own work does to P1 and P2.
//
// Where the wheel spans the joint with overlapping patches, the force run's
// spanning contact (sim/rail_end_patch_share.h) is no potential's gradient:
// the energy balance books its work, E_H ds + (p dF - F dp) / 2 per rail end,
// which loading and unloading through the overlap do not give back. Its
// conservative variant (conservative_spanning_contact: the gradient of the
// energy the balance books, over the two penetrations) is the same model
// less that work. The default suite checks the variant is what it says; the
// study (label study) runs seeded random force scenes under both laws and
// prints the P1 and P2 differences against the work (docs/forces.md, "What
// the merged law's own work does to P1 and P2").

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "models/hertz_ellipse.h"
#include "sim/rail_end_patch_share.h"
#include "sim/setting_checks.h"
#include "sim/simulate_crossing.h"
#include "sim/spanning_contact_study.h"
#include "tests/sim/random_scenes.h"

namespace railjoint {
namespace {

constexpr double kPi = std::numbers::pi;

// Two rail ends under a wheel of 0.475 m on a 300 mm crown (Hertz's ellipse,
// models/hertz_ellipse.h), their touching points x_0, x_1 along the track.
struct TwoRailEnds {
  double x0_m, x1_m;
  EllipticalHertz hertz = *elliptical_hertz({0.5 / 0.475, 0.5 / 0.3}, HertzMaterial{});
  double e_star_Pa = 210e9 / (2.0 * (1.0 - 0.09));
  RailEndPatch operator()(int i, double penetration_m) const {
    const double x = i == 0 ? x0_m : x1_m;
    if (!(penetration_m > 0.0)) return {x, 0.0, 0.0};
    const double G = hertz.hertz_constant_m_per_N2_3;
    const double force_N = std::pow(penetration_m / G, 1.5);
    return {x, hertz_patch(hertz, force_N).semi_axis_x_m, force_N};
  }
  std::array<double, 2> forces_N(const SpanningContact& s) const {
    return {s.share[0] * (*this)(0, std::max(0.0, s.effective_penetration_m[0])).force_N,
            s.share[1] * (*this)(1, std::max(0.0, s.effective_penetration_m[1])).force_N};
  }
};

// The work a law does around a closed loop of the two penetrations (a
// square: rail 0 in, rail 1 in, rail 0 out, rail 1 out), by the midpoint
// rule on `n` steps a side [J]. A potential's gradient gives 0.
template <class Law>
double loop_work_J(const TwoRailEnds& ends, const Law& law, std::array<double, 2> from_m, double side_m, int n) {
  double work_J = 0.0;
  const std::array<std::array<double, 2>, 4> legs = {{{side_m, 0.0}, {0.0, side_m}, {-side_m, 0.0}, {0.0, -side_m}}};
  std::array<double, 2> d = from_m;
  for (const auto& leg : legs) {
    for (int k = 0; k < n; ++k) {
      const std::array<double, 2> mid = {d[0] + 0.5 * leg[0] / n, d[1] + 0.5 * leg[1] / n};
      const std::array<double, 2> f = ends.forces_N(law(mid));
      work_J += f[0] * leg[0] / n + f[1] * leg[1] / n;
      d = {d[0] + leg[0] / n, d[1] + leg[1] / n};
    }
  }
  return work_J;
}

// The conservative variant is a potential's gradient: around a loop of the
// penetrations through overlapping patches (touching points 6 mm apart,
// semi-lengths 5.6-7.2 mm, 40-55 um: 60-95 kN a rail end) its work is the
// midpoint rule's error, where the merged law's is not. Measured: merged
// -3.0e-3 J, conservative -1.6e-7 J (falling as 1/n^2: the quadrature's)
// at n 400; Hertz's energy in the loop about 2 J. Allowed: 1e-5 J for the
// variant (60 times its residual), and the merged law's above 1e-3 J (the
// evidence that the variant removes something).
TEST(SpanningLaw, TheConservativeVariantDoesNoWorkAroundALoop) {
  const TwoRailEnds ends{-3e-3, 3e-3};
  const auto merged = [&](const std::array<double, 2>& d) { return spanning_contact(d, ends, ends.e_star_Pa); };
  const auto conservative = [&](const std::array<double, 2>& d) {
    return conservative_spanning_contact(d, ends, ends.e_star_Pa);
  };
  const double merged_J = loop_work_J(ends, merged, {40e-6, 25e-6}, 15e-6, 400);
  const double conservative_J = loop_work_J(ends, conservative, {40e-6, 25e-6}, 15e-6, 400);
  std::printf("work around the loop: merged %.3e J, conservative %.3e J\n", merged_J, conservative_J);
  EXPECT_LT(std::abs(conservative_J), 1e-5);
  EXPECT_GT(std::abs(merged_J), 1e-3);
}

// Where one rail end bears alone, or the patches lie apart (no share, the
// coupling through Boussinesq's far field a potential's as it is), both
// laws are the same contact: Hertz alone exactly, apart to the central
// difference's 1e-7.
TEST(SpanningLaw, OneRailEndOrPatchesApartAreTheMergedLaw) {
  const TwoRailEnds ends{-14e-3, 14e-3};
  const SpanningContact alone_m = spanning_contact({50e-6, 0.0}, ends, ends.e_star_Pa);
  const SpanningContact alone_c = conservative_spanning_contact({50e-6, 0.0}, ends, ends.e_star_Pa);
  EXPECT_EQ(ends.forces_N(alone_c)[0], ends.forces_N(alone_m)[0]);
  const std::array<double, 2> merged_N = ends.forces_N(spanning_contact({50e-6, 30e-6}, ends, ends.e_star_Pa));
  const std::array<double, 2> conservative_N =
      ends.forces_N(conservative_spanning_contact({50e-6, 30e-6}, ends, ends.e_star_Pa));
  std::printf("apart: merged %.6e %.6e N, conservative %.6e %.6e N\n", merged_N[0], merged_N[1], conservative_N[0],
              conservative_N[1]);
  for (int i = 0; i < 2; ++i) EXPECT_NEAR(conservative_N[i] / merged_N[i], 1.0, 1e-3);
}


// ---- The study: seeded random force scenes under both laws ----

enum class Group { lumped, continuous, free_hinge };
const char* group_name(Group g) {
  return g == Group::lumped ? "lumped" : g == Group::continuous ? "discrete, continuous" : "discrete, free hinge";
}

struct Scene {
  JointParams joint;
  WheelParams wheel;
  SimSettings settings;
};

// theta 30-90 deg, beta log-uniform 0.001-0.04 rad (shallow dips, where the
// patches overlap, as likely as steep ones), v 10-80 m/s, a thin disc at
// y -10..15 mm, pad 1e8-5e8 and ballast 2e7-1e8 N/m (the energy balance's
// random scenes, docs/forces.md, with the dip widened down to 0.001).
Scene draw_scene(testing_reference::PortableUniform& uniform, Group group, double step_s, double refined_s) {
  Scene s;
  s.joint.theta_rad = uniform(30.0, 90.0) * kPi / 180.0;
  s.joint.beta_rad = std::exp(uniform(std::log(0.001), std::log(0.04)));
  s.wheel.speed_m_per_s = uniform(10.0, 80.0);
  s.wheel.width_m = 0.0;
  s.wheel.lateral_m = uniform(-0.010, 0.015);
  TrackSupportSettings support;
  support.pad_stiffness_N_per_m = uniform(1e8, 5e8);
  support.ballast_stiffness_N_per_m = uniform(2e7, 1e8);
  InertialSettings& inertial = s.settings.make_inertial();
  inertial.force_time_step_s = step_s;
  s.settings.refined_time_step_s = refined_s;
  ElasticCrossingSettings& elastic = inertial.contact.emplace<ElasticCrossingSettings>();
  if (group == Group::lumped) {
    elastic.track.emplace().support = support;
  } else {
    DiscreteTrackSettings& track = elastic.discrete_track.emplace();
    track.support = support;
    if (group == Group::free_hinge) track.joint_bending_stiffness_N_m_per_rad = 0.0;
  }
  s.joint.length_m = std::max(1.0, rail_length_needed_m(s.joint, s.wheel, s.settings));
  return s;
}

struct LawRun {
  double p1_N = 0.0, p2_N = 0.0, static_N = 0.0, scale_J = 0.0, p1_time_s = 0.0, p2_time_s = 0.0, p2_window_end_s = 0.0;
  double apart_at_p1 = 0.0;  ///< HertzAtPeak::spanning_apart (0: one rail end bears)
  bool has_p2 = false, ok = false;
  std::string reason;
  // From the trace (merged law): the booked spanning work to P1's step and
  // in all, and whether the patches overlapped (a share below 1) by P1.
  double work_to_p1_J = 0.0, work_J = 0.0, least_share_to_p1 = 1.0;
  bool overlap_to_p1 = false, overlap_after_p1 = false;
};

// The spanning work the run's ledger books between two calls, per rail end
// (elastic_crossing_run.cpp, contact_stage): 0.5 (E_was + E_now) ds +
// 0.25 ((p_was + p_now) dF - (F_was + F_now) dp).
double booked_work_J(const SpanningTraceEntry& was, const SpanningTraceEntry& now) {
  double work_J = 0.0;
  const auto state = [](const SpanningTraceEntry& e, int i) {
    const double d = e.penetration_m[i];
    const double eff = d > 0.0 ? std::max(0.0, e.effective_penetration_m[i]) : 0.0;
    const double share = d > 0.0 ? e.share[i] : 1.0;
    const double hertz_N = d > 0.0 ? e.hertz_force_N[i] : 0.0;
    return std::array<double, 4>{share, 0.4 * hertz_N * eff, share * hertz_N, d - eff};  // s, E_H, F, p
  };
  for (int i = 0; i < 2; ++i) {
    const auto a = state(was, i), b = state(now, i);
    work_J += 0.5 * (a[1] + b[1]) * (b[0] - a[0]) + 0.25 * ((a[3] + b[3]) * (b[2] - a[2]) - (a[2] + b[2]) * (b[3] - a[3]));
  }
  return work_J;
}

LawRun run_law(const Scene& scene, SpanningLaw law) {
  std::vector<SpanningTraceEntry> trace;
  LawRun out;
  {
    const ScopedSpanningContactStudy study(law, &trace);
    const SimulationResult r = simulate_crossing(scene.joint, scene.wheel, scene.settings);
    out.ok = r.verdict.ok;
    out.reason = r.verdict.reason;
    if (!r.inertial() || !r.inertial()->forces) return out;
    const ForceOutcome& f = *r.inertial()->forces;
    out.p1_N = f.p1_N;
    out.p1_time_s = f.p1_time_s;
    out.static_N = f.static_N;
    out.scale_J = f.energy_scale_J;
    out.apart_at_p1 = f.hertz_patches.at_p1.spanning_apart;
    if (f.p2) {
      out.has_p2 = true;
      out.p2_N = f.p2->force_N;
      out.p2_time_s = f.p2->time_s;
      out.p2_window_end_s = f.p2->window_end_s;
    }
  }
  // P1's call: the largest sum of the two rail ends' forces (their normals
  // within a few 1e-2 rad of vertical).
  std::size_t p1_call = 0;
  double largest_N = -1.0;
  for (std::size_t k = 0; k < trace.size(); ++k) {
    const double sum_N = trace[k].share[0] * trace[k].hertz_force_N[0] + trace[k].share[1] * trace[k].hertz_force_N[1];
    if (sum_N > largest_N) largest_N = sum_N, p1_call = k;
  }
  for (std::size_t k = 0; k < trace.size(); ++k) {
    const SpanningTraceEntry& e = trace[k];
    if (k > 0) {
      const double w = booked_work_J(trace[k - 1], e);
      out.work_J += w;
      if (k <= p1_call) out.work_to_p1_J += w;
    }
    const bool both = e.penetration_m[0] > 0.0 && e.penetration_m[1] > 0.0;
    const bool overlap = both && std::min(e.share[0], e.share[1]) < 1.0;
    if (overlap && k <= p1_call) {
      out.overlap_to_p1 = true;
      out.least_share_to_p1 = std::min({out.least_share_to_p1, e.share[0], e.share[1]});
    }
    if (overlap && k > p1_call) out.overlap_after_p1 = true;
  }
  return out;
}

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[static_cast<std::size_t>(q * static_cast<double>(v.size() - 1))];
}

struct Stats {
  std::vector<double> dp1, dp2, work;
  double min_dp1 = HUGE_VAL, max_dp1 = -HUGE_VAL, min_dp2 = HUGE_VAL, max_dp2 = -HUGE_VAL;
  void add(double p1, double p2, double w) {
    dp1.push_back(std::abs(p1));
    dp2.push_back(std::abs(p2));
    work.push_back(std::abs(w));
    min_dp1 = std::min(min_dp1, p1), max_dp1 = std::max(max_dp1, p1);
    min_dp2 = std::min(min_dp2, p2), max_dp2 = std::max(max_dp2, p2);
  }
  void print(const char* what) const {
    if (dp1.empty()) {
      std::printf("| %s | 0 | | | |\n", what);
      return;
    }
    std::printf("| %s | %zu | %.1e / %.1e / %.1e (%+.1e..%+.1e) | %.1e / %.1e / %.1e (%+.1e..%+.1e) | %.1e / %.1e / %.1e |\n",
                what, dp1.size(), quantile(dp1, 0.5), quantile(dp1, 0.9), quantile(dp1, 1.0), min_dp1, max_dp1,
                quantile(dp2, 0.5), quantile(dp2, 0.9), quantile(dp2, 1.0), min_dp2, max_dp2, quantile(work, 0.5),
                quantile(work, 0.9), quantile(work, 1.0));
  }
};

// `count` scenes a group from `seed`: P1 and P2 under the conservative law
// against the merged one (relative), over the scenes whose patches overlapped
// at all, with the booked work to P1 over the energy scale; split by the
// merged run's verdict (vouched, or suspect: mostly both rail ends bearing
// at P1 nearer than a patch semi-length). Prints a row per such scene and a
// table; the vouched scene of each group whose P1 moved most is run again
// at half the step and a quarter of the refined step.
void law_study(std::uint64_t seed, int count) {
  constexpr double kStep_s = 4e-6, kRefined_s = 1e-6;
  std::printf("seed %llu, %d scenes a group\n", static_cast<unsigned long long>(seed), count);
  std::printf("group theta beta v y pad ballast | P1 merged [kN], / P0, cons./merged-1 | P2 merged [kN], cons./merged-1 | work to P1 / scale, least share, apart at P1 | verdict merged / cons.\n");
  std::vector<std::pair<std::string, Stats>> table;
  for (const Group group : {Group::lumped, Group::continuous, Group::free_hinge}) {
    testing_reference::PortableUniform uniform(seed * 1000 + static_cast<std::uint64_t>(group));
    Stats vouched, suspect;
    int overlapping = 0, only_after = 0;
    double worst = -1.0;
    std::optional<Scene> worst_scene;
    for (int n = 0; n < count; ++n) {
      const Scene scene = draw_scene(uniform, group, kStep_s, kRefined_s);
      const LawRun m = run_law(scene, SpanningLaw::merged);
      if (!m.overlap_to_p1 && !m.overlap_after_p1) continue;
      if (!m.overlap_to_p1) ++only_after;
      const LawRun c = run_law(scene, SpanningLaw::conservative);
      ++overlapping;
      const double dp1 = c.p1_N / m.p1_N - 1.0;
      const double dp2 = m.has_p2 && c.has_p2 ? c.p2_N / m.p2_N - 1.0 : 0.0;
      (m.ok ? vouched : suspect).add(dp1, dp2, m.work_to_p1_J / m.scale_J);
      if (m.ok && std::abs(dp1) > worst) worst = std::abs(dp1), worst_scene = scene;
      const auto& support = scene.settings.inertial()->elastic()->track
                                ? scene.settings.inertial()->elastic()->track->support
                                : scene.settings.inertial()->elastic()->discrete_track->support;
      std::printf("%d %5.1f %.4f %5.1f %+5.1f %.3e %.3e | %7.1f %5.3f %+.2e | %7.1f %+.2e | %+.2e %.3f %5.2f | %s / %s\n",
                  static_cast<int>(group), scene.joint.theta_rad * 180.0 / kPi, scene.joint.beta_rad,
                  scene.wheel.speed_m_per_s, 1e3 * scene.wheel.lateral_m, support.pad_stiffness_N_per_m,
                  support.ballast_stiffness_N_per_m, m.p1_N / 1e3, m.p1_N / m.static_N, dp1, m.p2_N / 1e3, dp2,
                  m.work_to_p1_J / m.scale_J, m.least_share_to_p1, m.apart_at_p1,
                  m.ok ? "ok" : m.reason.substr(0, 50).c_str(), c.ok ? "ok" : c.reason.substr(0, 50).c_str());
      if (std::abs(dp2) > 1e-3) {
        std::printf("  P2 at %.2f / %.2f ms (window to %.2f / %.2f ms), P1 at %.3f / %.3f ms (merged / conservative)\n",
                    1e3 * m.p2_time_s, 1e3 * c.p2_time_s, 1e3 * m.p2_window_end_s, 1e3 * c.p2_window_end_s,
                    1e3 * m.p1_time_s, 1e3 * c.p1_time_s);
      }
      // A run that vouches for its P1 holds it within 1 % whichever law
      // (self_check.cpp: kMergedLawP1ShiftOverP0), and its P2 too (measured
      // at most 1.5e-4 but where a suspect run's P2 was picked on another
      // peak: seed 4, 10.7 m/s, 0.15 ms after P1 under one law).
      if (m.ok) {
        EXPECT_LT(std::abs(dp1), 1e-2);
        EXPECT_LT(std::abs(dp2), 1e-2);
      }
    }
    std::printf("%s: %d of %d overlapped (%d of them only after P1)\n", group_name(group), overlapping, count,
                only_after);
    table.emplace_back(std::string(group_name(group)) + ", vouched", vouched);
    table.emplace_back(std::string(group_name(group)) + ", suspect", suspect);
    if (worst_scene) {
      // The same difference at a finer step: a number of the laws, not of the stepping.
      Scene fine = *worst_scene;
      fine.settings.make_inertial().force_time_step_s = 0.5 * kStep_s;
      fine.settings.refined_time_step_s = 0.25 * kRefined_s;
      const double coarse_dp1 =
          run_law(*worst_scene, SpanningLaw::conservative).p1_N / run_law(*worst_scene, SpanningLaw::merged).p1_N - 1;
      const double fine_dp1 = run_law(fine, SpanningLaw::conservative).p1_N / run_law(fine, SpanningLaw::merged).p1_N - 1;
      std::printf("%s, largest vouched P1 change: %+.3e at %.0e / %.0e s, %+.3e at %.0e / %.1e s\n", group_name(group),
                  coarse_dp1, kStep_s, kRefined_s, fine_dp1, 0.5 * kStep_s, 0.25 * kRefined_s);
    }
  }
  std::printf("| group | runs | |P1 cons./merged - 1|: median / p90 / max (range) | |P2 ...| | |work to P1| / scale |\n");
  for (const auto& [name, stats] : table) stats.print(name.c_str());
}

// The trace's booked work (booked_work_J, the ledger's rule) on the scene
// where the balance first showed it (docs/forces.md, "Where the balance's
// tail came from": free hinge, 25.2 m/s, theta 55.3 deg, beta 0.0109, y
// -4.5 mm, pad 2.75e8, ballast 5.97e7 N/m): the balance, not booking it, had
// gained 0.553 J over the 0.2 ms both rail ends bore, the contact energy
// 0.550 J more than the forces' work. The study reads the work the same way.
TEST(SpanningLaw, TheTracesWorkIsTheBalancesOldSurplus) {
  Scene scene;
  scene.joint.theta_rad = 55.3 * kPi / 180.0;
  scene.joint.beta_rad = 0.0109;
  scene.wheel.lateral_m = -0.0045;
  scene.wheel.width_m = 0.0;
  scene.wheel.speed_m_per_s = 25.2;
  scene.settings.make_inertial().wheel_load_N = 112.5e3;
  DiscreteTrackSettings& track =
      scene.settings.make_inertial().contact.emplace<ElasticCrossingSettings>().discrete_track.emplace();
  track.support.pad_stiffness_N_per_m = 2.75e8;
  track.support.ballast_stiffness_N_per_m = 5.97e7;
  track.joint_bending_stiffness_N_m_per_rad = 0.0;
  scene.joint.length_m = std::max(1.0, rail_length_needed_m(scene.joint, scene.wheel, scene.settings));
  const LawRun m = run_law(scene, SpanningLaw::merged);
  std::printf("booked spanning work %.4f J in all, %.4f J to P1, of %.2f J (%.2e); least share %.3f\n", m.work_J,
              m.work_to_p1_J, m.scale_J, m.work_J / m.scale_J, m.least_share_to_p1);
  EXPECT_NEAR(std::abs(m.work_J), 0.55, 0.01);
  EXPECT_TRUE(m.overlap_to_p1);
}

// A lumped-track run at 16 m/s over a 0.01 rad dip (seed 3's largest
// P1 change, its printed parameters): the patches overlap at the dip's
// bottom (R beta 4.75 mm against two semi-lengths of some 8 mm), the
// merged law does work of its own there, and P1 moves by more than the run
// can vouch for against the conservative law (measured -2.8 % on seed 3's
// scene). The run says so (self_check.cpp); before, it vouched for its P1.
TEST(SpanningLaw, ARunWhosePatchesOverlappedBeforeP1SaysSo) {
  Scene scene;
  scene.joint.theta_rad = 82.2 * kPi / 180.0;
  scene.joint.beta_rad = 0.0100;
  scene.wheel.lateral_m = 0.0006;
  scene.wheel.width_m = 0.0;
  scene.wheel.speed_m_per_s = 16.2;
  LumpedTrackSettings& track =
      scene.settings.make_inertial().contact.emplace<ElasticCrossingSettings>().track.emplace();
  track.support.pad_stiffness_N_per_m = 1.264e8;
  track.support.ballast_stiffness_N_per_m = 3.862e7;
  scene.joint.length_m = std::max(1.0, rail_length_needed_m(scene.joint, scene.wheel, scene.settings));
  const LawRun merged = run_law(scene, SpanningLaw::merged);
  const LawRun conservative = run_law(scene, SpanningLaw::conservative);
  std::printf("P1 %.1f kN (%.3f P0), conservative %.1f kN (%+.2e); work to P1 %.2e of the scale; %s\n",
              merged.p1_N / 1e3, merged.p1_N / merged.static_N, conservative.p1_N / 1e3,
              conservative.p1_N / merged.p1_N - 1.0, merged.work_to_p1_J / merged.scale_J, merged.reason.c_str());
  ASSERT_TRUE(merged.overlap_to_p1);
  EXPECT_GT(std::abs(conservative.p1_N / merged.p1_N - 1.0), 1e-2);
  EXPECT_LT(std::abs(conservative.p1_N - merged.p1_N), kMergedLawP1ShiftOverP0 * merged.static_N);
  EXPECT_FALSE(merged.ok);
  EXPECT_NE(merged.reason.find("merged-patch law"), std::string::npos) << merged.reason;
}

TEST(SpanningLawStudy, Seed1) { law_study(1, 30); }
TEST(SpanningLawStudy, Seed2) { law_study(2, 30); }
TEST(SpanningLawStudy, Seed3) { law_study(3, 30); }
TEST(SpanningLawStudy, Seed4) { law_study(4, 30); }
TEST(SpanningLawStudy, Seed5) { law_study(5, 30); }

// The shipped force scenes (scenes/forces/lumped_track.toml,
// discrete_track.toml: square joint, y 0, 50 m/s) over dips from 0.005 to
// 0.03 rad under both laws: P1, the verdict, and P1's change.
TEST(SpanningLawStudy, ShippedScenesOverDips) {
  std::printf("track     dip     P1 merged [kN]  P1 / P0  P1 cons./merged - 1  P2 cons./merged - 1  verdict\n");
  for (const bool lumped : {true, false}) {
    for (const double beta : {0.005, 0.01, 0.02, 0.03}) {
      Scene scene;
      scene.joint.theta_rad = 0.5 * kPi;
      scene.joint.beta_rad = beta;
      scene.wheel.lateral_m = 0.0;
      scene.wheel.width_m = 0.0;
      scene.wheel.speed_m_per_s = 50.0;
      ElasticCrossingSettings& elastic = scene.settings.make_inertial().contact.emplace<ElasticCrossingSettings>();
      if (lumped) {
        elastic.track.emplace();
      } else {
        elastic.discrete_track.emplace();
      }
      scene.joint.length_m = std::max(1.0, rail_length_needed_m(scene.joint, scene.wheel, scene.settings));
      const LawRun m = run_law(scene, SpanningLaw::merged);
      const LawRun c = run_law(scene, SpanningLaw::conservative);
      std::printf("%-9s %.3f  %8.1f        %5.3f    %+.2e            %+.2e            %s\n", lumped ? "lumped" : "discrete",
                  beta, m.p1_N / 1e3, m.p1_N / m.static_N, c.p1_N / m.p1_N - 1.0, c.p2_N / m.p2_N - 1.0,
                  m.ok ? "ok" : m.reason.substr(0, 70).c_str());
      if (m.ok) {
        EXPECT_LT(std::abs(c.p1_N / m.p1_N - 1.0), 1e-2);
      }
    }
  }
}

}  // namespace
}  // namespace railjoint
