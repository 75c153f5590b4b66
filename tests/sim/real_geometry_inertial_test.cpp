// Inertial runs with a linear contact spring on real geometry (the rigid
// runs are judged on random scenes: random_scene_accuracy_test.cpp). There
// is no closed form for a spring on a crowned head; what is known without
// the code under test is the limit: a crown of 1000 m drops the head by
// y^2 / (2 rho) < 3e-8 m across a 15 mm wheel and tilts its normal by
// y / rho < 1e-5, so a run on it must give the flat head's peak force and
// first jump (the flat head runs on the meshes, the crown on the analytic
// tops: two narrow phases, one answer).

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>

#include <gtest/gtest.h>

#include "sim/crossing_cases.h"
#include "sim/impact_force_estimate.h"
#include "sim/simulate_crossing.h"
#include "tests/sim/real_geometry_inertial.h"

namespace railjoint {
namespace {

struct SpringRun {
  double peak_N;
  double jump_Ns;
};

SpringRun spring_run(const CrossingCase& c) {
  SimSettings s;
  s.make_inertial();
  s.run_out_time_s = 0.004;
  const double W = s.inertial()->wheel_load_N + c.wheel.mass_kg * kStandardGravity_m_per_s2;
  s.make_inertial().contact.emplace<LinearContactSettings>().stiffness_N_per_m =
      linearised_hertz_stiffness_N_per_m(HertzContact{}, W);
  JointParams joint = c.joint;
  joint.length_m = 3.0;
  const SimulationResult r = simulate_crossing(joint, c.wheel, s);
  EXPECT_TRUE(r.inertial() && r.inertial()->compliant) << c.name;
  return {r.inertial()->peak_force_N, r.impact_found() ? r.impulse_Ns() : 0.0};
}

TEST(RealGeometryInertial, LinearContactOnAFlatCrownGivesTheFlatHeadsPeak) {
  // Scenario 1 (theta 45 deg) and an edge strike (theta 30 deg, y 12 mm),
  // a 15 mm wheel so both runs simulate the same wheel (a thin disc's
  // stand-in on the meshes is a 1 mm cylinder).
  for (const auto& [theta_deg, y_m] : {std::pair{45.0, 0.002}, std::pair{30.0, 0.010}}) {
    const CrossingCase flat = inclined_crossing("flat", theta_deg, y_m, 50.0, 0.015);
    CrossingCase crown = flat;
    crown.joint.crown_radius_m = 1000.0;
    const SpringRun on_flat = spring_run(flat);
    const SpringRun on_crown = spring_run(crown);
    std::cout << "theta " << theta_deg << " deg: peak flat " << on_flat.peak_N << " N, crown 1000 m " << on_crown.peak_N
              << " N (" << on_crown.peak_N / on_flat.peak_N - 1 << ")\n";
    ASSERT_TRUE(std::isfinite(on_crown.peak_N));
    // Measured 8.1e-6 (45 deg) and 5.4e-6 (30 deg), the crown's own 1e-5
    // order; 1e-4 is ten times that.
    EXPECT_NEAR(on_crown.peak_N / on_flat.peak_N, 1.0, 1e-4) << theta_deg;
  }
}

TEST(RealGeometryInertial, LinearContactRunsOn60E1UnderAConeWithAFiniteForce) {
  // The first request with the spring instead of Hertz: it must run,
  // and its peak must exceed the static load (the joint is a dip: the
  // wheel's vertical velocity reverses on the spring) by less than the
  // rigid-track P1 of a joint whose total dip angle is beta (Jenkins:
  // P0 + beta v sqrt(k M)), which the two-rail spring stays below
  // (inertial_crossing_test.cpp: measured -2.9 % on the flat head).
  CrossingCase c = inclined_crossing("60e1", 45.0, 0.005, 30.0, 0.07);
  c.joint.rail_profile = RailProfile::en_60e1;
  c.joint.half_width_m = 0.036;
  c.wheel.conicity = 0.025;
  const SpringRun r = spring_run(c);
  SimSettings s;
  s.make_inertial();
  const double W = s.inertial()->wheel_load_N + c.wheel.mass_kg * kStandardGravity_m_per_s2;
  const double k = linearised_hertz_stiffness_N_per_m(HertzContact{}, W);
  const double p1 = W + c.joint.beta_rad * c.wheel.speed_m_per_s * std::sqrt(k * c.wheel.mass_kg);
  std::cout << "60E1 + 1:40, 30 m/s: peak " << r.peak_N << " N, P0 " << W << " N, P1 " << p1 << " N\n";
  ASSERT_TRUE(std::isfinite(r.peak_N));
  EXPECT_GT(r.peak_N, W);
  EXPECT_LT(r.peak_N, p1);
}

TEST(RealGeometryInertial, SmallLandingsOn60E1AreMeasuredOrTheRunSaysItCannot) {
  // Scenes 21 and 57 of the real-geometry inertial study's seed 1 (46.3 and
  // 34.2 m/s): the wheel flies 0.9 and 1.5 mm after the strike and lands
  // with J = 1.17 and 2.61 N s (real_inertial_reference, independent of the
  // run), below the detector's 1e-4 M v for fast steps; they went missing
  // and the runs vouched for a landing error of -1. Stepped at dt, the
  // measured landing is sqrt(J^2 + (W dt)^2), as if the wheel met the rail
  // after a further fall of g_W dt^2 / 2 (u^2 + 2 g_W d): to leading order
  // off by (W dt)^2 / (2 J^2), the self-check's bias. Measured on both
  // scenes at eight steps from 4e-6 to 1.25e-7 s: within 8.5e-5 N s of it
  // from 4e-6 to 7e-7 s (the leading order is 3.8e-3 N s off at 4e-6 s on
  // #21), within 3.8e-4 N s at every step, the rest moving irregularly with
  // the step (not the strike's error, 7e-6 N s at every step); 1.9e-4 N s
  // at most at the steps below. 8e-4 N s, twice the largest seen, holds the
  // law to 13 % where the check acts (#21 at 1e-6 s: 6.2e-3 N s, the run
  // suspect) and to 1 % at 4e-6 s.
  const std::vector<testing_reference::RandomCrossing> scenes = testing_reference::rail_60e1_crossings(58, 1);
  for (const int index : {21, 57}) {
    const testing_reference::RandomCrossing& c = scenes[static_cast<std::size_t>(index)];
    for (const double step_s : {4e-6, 2e-6, 1e-6, 2.5e-7}) {
      SimSettings s;
      s.make_inertial();
      s.refined_time_step_s = step_s;
      const double W = s.inertial()->wheel_load_N + c.wheel.mass_kg * kStandardGravity_m_per_s2;
      JointParams joint = c.joint;
      joint.length_m = std::max(joint.length_m, rail_length_needed_m(joint, c.wheel, s));
      const SimulationResult r = simulate_crossing(joint, c.wheel, s);
      reference::Geometry g = testing_reference::reference_geometry_of(c, s);
      g.half_length_m = r.model->joint.length_m / 2.0;
      const testing_reference::RealInertialReference ref =
          testing_reference::real_inertial_reference(g, c, W, s.approach_distance_m);
      ASSERT_TRUE(ref.flies_after) << c.name;
      ASSERT_TRUE(r.second_impact.has_value()) << c.name << " at " << step_s << " s: the landing is missing";
      const double J = ref.landing_Ns, load_Ns = W * step_s;
      const double error = (r.second_impact->impulse_Ns - J) / J;
      const double bias = load_Ns * load_Ns / (2.0 * J * J);
      std::cout << c.name << " step " << step_s << " s: landing " << r.second_impact->impulse_Ns << " N s, reference "
                << J << " N s, error " << error << ", bias law " << bias << " (" << error / bias << "x), "
                << (r.verdict.ok ? "ok" : r.verdict.reason) << "\n";
      EXPECT_NEAR(r.second_impact->impulse_Ns, std::hypot(J, load_Ns), 8e-4) << c.name << " at " << step_s;
      if (step_s < 1e-6) {
        // 3e-4 of bias: both landings vouched and within the studies' 1e-3.
        EXPECT_TRUE(r.verdict.ok) << c.name << ": " << r.verdict.reason;
        EXPECT_LE(std::abs(error), 1e-3) << c.name;
      } else if (index == 21) {
        // 5e-3 and more: the run says so, and names the fine step it needs.
        EXPECT_FALSE(r.verdict.ok) << c.name;
        EXPECT_NE(r.verdict.reason.find("a fine step: lower sim.refined_time_step"), std::string::npos)
            << r.verdict.reason;
      }
    }
  }
}

// The step a run asks for resolves the landing. It is J sqrt(2e-3) / W of
// the measured J, which is (W dt)^2 / (2 J^2) above the true one (0.5 % at
// #21's 1e-6 s): at 0.95 of it the run is vouched. #21 at the default steps
// lands in a fine step and asks for sim.refined_time_step (4.38e-7 s); #57
// at fixed steps of 2e-6 s (both settings) asks for sim.time_step and
// sim.refined_time_step with it (9.76e-7 s).
void expect_the_asked_step_resolves_it(int index, SimSettings s, bool fixed) {
  const testing_reference::RandomCrossing c = testing_reference::rail_60e1_crossings(58, 1)[static_cast<std::size_t>(index)];
  JointParams joint = c.joint;
  joint.length_m = std::max(joint.length_m, rail_length_needed_m(joint, c.wheel, s));
  const SimulationResult asked = simulate_crossing(joint, c.wheel, s);
  const std::string advice =
      fixed ? "a coarse step: lower sim.time_step [s] to below " : "a fine step: lower sim.refined_time_step [s] to below ";
  const std::size_t at = asked.verdict.reason.find(advice);
  ASSERT_NE(at, std::string::npos) << asked.verdict.reason;
  EXPECT_EQ(fixed, asked.verdict.reason.find("and sim.refined_time_step with it") != std::string::npos);
  const double step_s = 0.95 * std::stod(asked.verdict.reason.substr(at + advice.size()));
  s.refined_time_step_s = step_s;
  if (fixed) s.time_step_s = step_s;
  const SimulationResult resolved = simulate_crossing(joint, c.wheel, s);
  std::cout << c.name << ": asked for " << step_s / 0.95 << " s; at " << step_s << " s: "
            << (resolved.verdict.ok ? "ok" : resolved.verdict.reason) << "\n";
  EXPECT_TRUE(resolved.verdict.ok) << resolved.verdict.reason;
}

TEST(RealGeometryInertial, TheStepASmallLandingAsksForResolvesIt) {
  SimSettings s;
  s.make_inertial();
  expect_the_asked_step_resolves_it(21, s, false);
  s.time_step_s = s.refined_time_step_s = 2e-6;
  expect_the_asked_step_resolves_it(57, s, true);
}

}  // namespace
}  // namespace railjoint
