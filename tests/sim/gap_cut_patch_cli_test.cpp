// A force run across an end-post gap whose P1 is borne by a rail end whose
// Hertz patch the gap cuts (its touching point less than a patch
// semi-length from its cut's edge, or on the edge) says it cannot vouch for
// P1: against the boundary-element solver such a rail end carries 0.77 of
// Hertz's force with the touching point on the edge, down to about 0.5 over
// the gap, and the coupled pair is -3 % to +66 % off (docs/forces.md,
// "Across an end-post gap"; tests/sim/rail_end_share_gap_test.cpp). The
// same run with the gap closed (one body, which the solver's check of the
// spanning contact covers) and a gap run whose patches clear the gap are
// vouched for. The scenes are the docs' gap table's (docs/forces.md, the
// disc's width on gap and step joints) and a wheel centred over a gap.

#include <algorithm>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/run_cli.h"

namespace {

using railjoint::testing_support::run_railjoint;
using railjoint::testing_support::split_json_and_tail;

struct ForceRun {
  int exit_code = -1;
  std::string verdict;
  std::string reason;
  nlohmann::json forces;
};

ForceRun simulate_lumped(const std::string& overrides) {
  const auto r =
      run_railjoint("simulate " + std::string(RAILJOINT_SOURCE_DIR) + "/scenes/forces/lumped_track.toml --json " +
                    overrides);
  ForceRun run;
  run.exit_code = r.exit_code;
  // A suspect run adds one line after its JSON.
  const nlohmann::json j = nlohmann::json::parse(split_json_and_tail(r.output).json);
  run.verdict = j.at("sim").at("verdict").get<std::string>();
  run.reason = j.at("sim").at("verdict_reason").get<std::string>();
  run.forces = j.at("sim").at("forces");
  return run;
}

void expect_vouched_for(const ForceRun& run) {
  EXPECT_EQ(run.exit_code, 0) << run.reason;
  EXPECT_EQ(run.verdict, "ok") << run.reason;
}

// The bearing rail ends' d / a at a peak, the least of them (over 1 % of
// the force, as the check counts them).
double least_edge_distance(const nlohmann::json& at_peak) {
  double total_N = 0.0;
  for (const auto& e : at_peak.at("rail_ends")) total_N += e.at("normal_force_N").get<double>();
  double least = 1e300;
  for (const auto& e : at_peak.at("rail_ends")) {
    if (e.at("normal_force_N").get<double>() > 0.01 * total_N && !e.at("cut_edge_distance_semi_lengths").is_null()) {
      least = std::min(least, e.at("cut_edge_distance_semi_lengths").get<double>());
    }
  }
  return least;
}

// A 30 deg cut over a 2 mm gap at 20 m/s, the wheel 15 mm off the centre
// line: the wheel lands on the outgoing rail's face under half a patch
// semi-length from its edge (d / a 0.47: the flight is short at 20 m/s; at
// 50 m/s it lands 2.5 a on), its patch cut by the gap.
TEST(GapCutPatch, AGapRunWhoseP1PatchTheGapCutsIsNotVouchedFor) {
  const ForceRun run = simulate_lumped(
      "--set joint.gap=0.002 --set joint.theta_deg=30 --set wheel.y=0.015 --set wheel.speed=20");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.verdict, "suspect");
  EXPECT_NE(run.reason.find("P1 is borne across the 2 mm end-post gap by rail end 1"), std::string::npos)
      << run.reason;
  EXPECT_NE(run.reason.find("0.77 of Hertz's force"), std::string::npos) << run.reason;
  EXPECT_NE(run.reason.find("Across an end-post gap"), std::string::npos) << run.reason;
  // What the check read: the outgoing rail end alone bears, its touching
  // point on its face within a patch semi-length of the edge.
  const nlohmann::json& ends = run.forces.at("hertz_at_p1").at("rail_ends");
  ASSERT_EQ(ends.size(), 1u);
  EXPECT_EQ(ends[0].at("rail"), 1);
  EXPECT_FALSE(ends[0].at("at_cut_edge").get<bool>());
  const double d_over_a = ends[0].at("cut_edge_distance_semi_lengths").get<double>();
  EXPECT_GT(d_over_a, 0.0);
  EXPECT_LT(d_over_a, 1.0);
  // The run is otherwise sound: P1 is the only thing not vouched for.
  EXPECT_EQ(run.reason.find(';'), std::string::npos) << run.reason;
}

// The same run with the rail ends abutting (joint.gap 0): one body under
// the wheel; the patch reaching past the outgoing rail's edge lies on the
// incoming rail, which the run's coupled contact takes (the solver's check
// of the spanning contact), so the run is vouched for as before.
TEST(GapCutPatch, TheSameRunWithTheGapClosedIsVouchedFor) {
  const ForceRun run = simulate_lumped(
      "--set joint.gap=0 --set joint.theta_deg=30 --set wheel.y=0.015 --set wheel.speed=20");
  expect_vouched_for(run);
  // Its patch does reach past the edge: the flag is the gap's, not d < a's.
  EXPECT_LT(least_edge_distance(run.forces.at("hertz_at_p1")), 1.0);
}

// A 45 deg cut over a 2 mm gap at 50 m/s, 10 mm off the centre line: the
// wheel lands 3.6 patch semi-lengths onto the outgoing rail (the 0.03 rad
// dip throws it that far), clear of the gap at P1 and at P2, where the
// solver finds the coupling through the wheel right within 0.14 %.
TEST(GapCutPatch, AGapRunWhosePatchesClearTheGapIsVouchedFor) {
  const ForceRun run = simulate_lumped(
      "--set joint.gap=0.002 --set joint.theta_deg=45 --set wheel.y=0.01 --set wheel.speed=50");
  expect_vouched_for(run);
  EXPECT_GE(least_edge_distance(run.forces.at("hertz_at_p1")), 1.0);
  EXPECT_GE(least_edge_distance(run.forces.at("hertz_at_p2")), 1.0);
}

// A wheel (R 0.475 m) over a 10 mm square gap on otherwise level rail
// (beta 1e-4): a circle wider than the gap, its centre over it, rests on
// both corners, so at P1 each rail end bears on its cut's edge, d = 0, the
// empirical constant's place. The touching points lie 10 mm apart, over a
// patch semi-length (1.6 of the larger), so the spanning check passes it:
// the gap's flag alone says P1 is not vouched for.
TEST(GapCutPatch, AWheelOverASquareGapBearsOnBothEdgesAndIsNotVouchedFor) {
  const ForceRun run = simulate_lumped(
      "--set joint.gap=0.01 --set joint.beta=0.0001 --set wheel.speed=30");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.verdict, "suspect");
  const nlohmann::json& at_p1 = run.forces.at("hertz_at_p1");
  ASSERT_EQ(at_p1.at("rail_ends").size(), 2u);
  for (const auto& e : at_p1.at("rail_ends")) {
    EXPECT_TRUE(e.at("at_cut_edge").get<bool>()) << e;
    EXPECT_EQ(e.at("cut_edge_distance_semi_lengths").get<double>(), 0.0) << e;
  }
  EXPECT_GE(at_p1.at("spanning_apart").get<double>(), 1.0);
  EXPECT_NE(run.reason.find("across the 10 mm end-post gap by rail end"), std::string::npos) << run.reason;
  EXPECT_NE(run.reason.find("on its cut's edge (the empirical Hertz constant"), std::string::npos) << run.reason;
  EXPECT_EQ(run.reason.find("both rail ends bear at P1"), std::string::npos) << run.reason;
}

}  // namespace
