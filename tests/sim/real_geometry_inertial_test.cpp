// Inertial runs with a linear contact spring on real geometry (the rigid
// runs are judged on random scenes: random_scene_accuracy_test.cpp). There
// is no closed form for a spring on a crowned head; what is known without
// the code under test is the limit: a crown of 1000 m drops the head by
// y^2 / (2 rho) < 3e-8 m across a 15 mm wheel and tilts its normal by
// y / rho < 1e-5, so a run on it must give the flat head's peak force and
// first jump (the flat head runs on the meshes, the crown on the analytic
// tops: two narrow phases, one answer).

#include <cmath>
#include <iostream>

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
  // with 1.17 and 2.61 N s (real_inertial_reference, independent of the
  // run), below the detector's 1e-4 M v for fast steps; they went missing
  // and the runs vouched for a landing error of -1. At the default fine step
  // (1e-6 s) the load's impulse over it, 0.12 N s, is a tenth of the first
  // landing: its jump is off by (W dt)^2 / (2 J^2) = 5e-3, and the run must
  // say so. At 2.5e-7 s that is 3e-4 (measured 4.9e-4 and 5.2e-5): both
  // landings are found, vouched and within the studies' 1e-3.
  const std::vector<testing_reference::RandomCrossing> scenes = testing_reference::rail_60e1_crossings(58, 1);
  for (const int index : {21, 57}) {
    const testing_reference::RandomCrossing& c = scenes[static_cast<std::size_t>(index)];
    for (const double step_s : {1e-6, 2.5e-7}) {
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
      const double error = (r.second_impact->impulse_Ns - ref.landing_Ns) / ref.landing_Ns;
      std::cout << c.name << " step " << step_s << " s: landing " << r.second_impact->impulse_Ns << " N s, reference "
                << ref.landing_Ns << " N s, error " << error << ", " << (r.verdict.ok ? "ok" : r.verdict.reason) << "\n";
      if (step_s < 1e-6) {
        EXPECT_TRUE(r.verdict.ok) << c.name << ": " << r.verdict.reason;
        EXPECT_LE(std::abs(error), 1e-3) << c.name;
      } else if (index == 21) {
        EXPECT_FALSE(r.verdict.ok) << c.name;
        EXPECT_NE(r.verdict.reason.find("landing"), std::string::npos) << r.verdict.reason;
      }
    }
  }
}

}  // namespace
}  // namespace railjoint
