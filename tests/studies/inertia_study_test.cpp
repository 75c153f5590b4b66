// The quick inertia study (scenes/studies/inertia_study.h) and the
// `railjoint study inertia` command: what each row must show follows from the
// kinematic model and the pivot model (models/liftoff.h), derived in the comments.

#include "scenes/studies/inertia_study.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

#include <gtest/gtest.h>

#include "tests/support/run_cli.h"
#include "tests/support/scratch_dir.h"

namespace railjoint {
namespace {

namespace fs = std::filesystem;

const InertiaStudy& quick_study() {
  static const InertiaStudy study = run_inertia_study(true);
  return study;
}

TEST(InertiaStudy, QuickSweepShowsWhereTheGlueMatters) {
  const InertiaStudy& s = quick_study();
  // theta 30 deg x v {10, 30, 50} x y_w {-15, 1.5, 15} mm.
  ASSERT_EQ(s.sweep.size(), 9u);
  for (const InertiaSweepPoint& p : s.sweep) {
    std::cout << "v " << p.speed_m_per_s << " y " << p.lateral_m * 1e3 << " mm: kinematic " << p.kinematic_jump_Ns
              << ", first " << p.first_jump_Ns << ", landing " << p.landing_jump_Ns << ", total " << p.total_impulse_Ns
              << " N s, lift-off " << p.liftoff << " (predicted " << p.liftoff_predicted << ")\n";
    // Every speed is above v_c ~ 8.7 m/s of the 112.5 kN load (pivot model).
    if (p.scenario == ImpactScenario::one) {
      // y_w = 1.5 mm < y_t = 4.11 mm: plain V, no convex corner: the wheel
      // stays on the rail and the jump is the kinematic one (the accuracy
      // target, 0.5 %).
      EXPECT_FALSE(p.liftoff);
      EXPECT_NEAR(p.first_jump_Ns / p.kinematic_jump_Ns, 1.0, 5e-3);
      EXPECT_NEAR(p.total_impulse_Ns, p.first_jump_Ns, 1e-9);
    } else if (!p.on_landing) {
      // y_w = 15 mm: the strike at A is the kinematic jump, then the wheel
      // cannot follow the pivot: it flies and lands once more.
      EXPECT_TRUE(p.liftoff);
      EXPECT_TRUE(p.liftoff_predicted);
      EXPECT_NEAR(p.first_jump_Ns / p.kinematic_jump_Ns, 1.0, 5e-3);
      EXPECT_GT(p.landing_jump_Ns, 0.0);
      EXPECT_NEAR(p.total_impulse_Ns, p.first_jump_Ns + p.landing_jump_Ns, 1e-6);
    } else {
      // y_w = -15 mm: the wheel leaves the corner it rolls off before the
      // pivot makes it fall at v tan(alpha): it lands slower than the glued
      // wheel, a smaller jump.
      EXPECT_TRUE(p.liftoff);
      EXPECT_LT(p.first_jump_Ns, p.kinematic_jump_Ns);
    }
  }
}

TEST(InertiaStudy, QuickThresholdAndPeakForce) {
  const InertiaStudy& s = quick_study();
  ASSERT_EQ(s.thresholds.size(), 1u);
  const LiftoffThresholdPoint& t = s.thresholds.front();
  std::cout << t.name << ": model " << t.model_speed_m_per_s << " m/s, simulated " << t.sim_below_m_per_s << " .. "
            << t.sim_above_m_per_s << " m/s\n";
  // The load is chosen so the model puts v_c at 30 m/s; four bisection steps
  // over +-15 % leave a bracket of 30 % / 16 = 1.9 %. The full bisection
  // found the simulated threshold 1.3 % above the model (detection needs
  // ~2 um of flight): the bracket must lie within 3 % of the model.
  EXPECT_NEAR(t.model_speed_m_per_s, 30.0, 1e-9);
  EXPECT_LT(t.sim_below_m_per_s, t.sim_above_m_per_s);
  EXPECT_GT(t.sim_above_m_per_s, 0.97 * t.model_speed_m_per_s);
  EXPECT_LT(t.sim_below_m_per_s, 1.03 * t.model_speed_m_per_s);
  ASSERT_EQ(s.peaks.size(), 2u);
  const PeakForcePoint& p = s.peaks.front();
  std::cout << "peak " << p.peak_force_N << " N, P1 rigid track " << p.p1_rigid_track_N << " N\n";
  // Scenario 1 at 50 m/s: 3 % below P1 (tests/sim/inertial_crossing_test.cpp explains why); 6 %.
  EXPECT_EQ(p.scenario, 1);
  EXPECT_NEAR(p.peak_force_N / p.p1_rigid_track_N, 1.0, 6e-2);
  // Scenario 1 has no edge strike: its jump is beta v, both P1 forms agree.
  EXPECT_NEAR(p.jump_velocity_change_m_per_s, 0.03 * 50.0, 1.5e-3);
  EXPECT_EQ(p.edge_pivot_time_s, 0.0);
  // (pi/2) sqrt(M / k) with k = 1.5346e9 N/m, M = 750 kg: 1.0981 ms.
  EXPECT_NEAR(p.spring_quarter_period_s, 1.0981e-3, 1e-6);

  const PeakForcePoint& edge = s.peaks.back();
  EXPECT_EQ(edge.scenario, 2);
  // The pivot spans the contact lead x_A (about 20 mm, table 4.1) plus
  // R sin(beta/2) = 7.12 mm: (20 + 7.1) mm / 50 m/s = 0.54 ms.
  EXPECT_NEAR(edge.edge_pivot_time_s * 50.0, 0.020 + 0.475 * std::sin(0.015), 1e-3);
  // The spring feels beta v, not the edge jump (inertial_crossing_test.cpp).
  EXPECT_NEAR(edge.peak_force_N / edge.p1_rigid_track_N, 1.0, 6e-2);
  EXPECT_LT(edge.peak_force_N, 0.7 * edge.p1_from_jump_N);
}

TEST(InertiaStudy, CommandWritesTablesAndReport) {
  const fs::path out = testing_support::scratch_path("study_cli_inertia");
  const testing_support::RunResult r =
      testing_support::run_railjoint("study inertia --quick --no-figures --out " + out.string());
  std::cout << r.output;
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("Lift-off speed"), std::string::npos);
  for (const char* name : {"inertia_sweep.csv", "inertia_thresholds.csv", "inertia_peaks.csv", "inertia_quick.md"}) {
    EXPECT_TRUE(fs::exists(out / name)) << name;
  }
  std::ifstream csv(out / "inertia_sweep.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header.rfind("theta_deg,speed_m_per_s,y_w_m,scenario,", 0), 0u) << header;
}

}  // namespace
}  // namespace railjoint
