// The run's own check (sim/self_check.h) on hand-made results: what a
// landing too small for the step it lands in asks the user to lower.

#include "sim/self_check.h"

#include <cmath>
#include <iostream>
#include <string>

#include <gtest/gtest.h>

namespace railjoint {
namespace {

constexpr double kLoad_N = 119857.5;  // W: 112.5 kN wheel load + 750 kg x 9.81 m/s^2

// A rigid inertial run whose joint impact (100 N s, its estimators agreeing)
// is followed by a landing of landing_Ns in a step of step_s [s].
SimulationResult run_with_landing(double landing_Ns, double step_s) {
  SimulationResult r;
  RigidJump joint;
  joint.jump_Ns = joint.from_contacts_Ns = 100.0;
  r.impact = JointImpact(joint);
  for (int k = 0; k < 4; ++k) {
    WheelSample s;
    s.time_s = k * 1e-6 + (k == 3 ? step_s - 1e-6 : 0.0);
    r.trajectory.samples.push_back(s);
  }
  ImpactEvent strike, landing;
  strike.first_sample = 1;
  landing.first_sample = 3;
  landing.momentum_jump_Ns = landing_Ns;
  landing.landing = true;
  r.trajectory.impacts = {strike, landing};
  InertialOutcome out;
  out.static_load_N = kLoad_N;
  out.joint_impact_index = 0;
  r.outcome = out;
  return r;
}

// The check's reason for a landing of landing_Ns in a step of step_s [s]:
// it must name `advice` (and `also` too when given, else nothing after it)
// and ask for the step at which the bias (W dt)^2 / (2 J^2) reaches the
// limit, dt = J sqrt(2 limit) / W.
void expect_advice(double landing_Ns, double step_s, const SimSettings& settings, const std::string& advice,
                   const std::string& also = "") {
  const SimVerdict v = inertial_self_check(run_with_landing(landing_Ns, step_s), settings);
  std::cout << v.reason << "\n";
  EXPECT_FALSE(v.ok);
  const std::size_t at = v.reason.find(advice + " [s] to below ");
  ASSERT_NE(at, std::string::npos) << v.reason;
  const std::string rest = v.reason.substr(at + advice.size() + 14);
  const double needed_s = landing_Ns * std::sqrt(2.0 * SelfCheckLimits{}.landing_step_bias) / kLoad_N;
  EXPECT_NEAR(std::stod(rest), needed_s, 2e-5 * needed_s);  // printed to 6 digits
  EXPECT_EQ(rest.find("sim."), also.empty() ? std::string::npos : rest.find(also)) << v.reason;
}

TEST(SelfCheck, ALandingInAFineStepAsksForTheFineStepItNeeds) {
  // 60E1#21's landing (1.17 N s) at the default fine step, 1e-6 s: bias
  // (0.1199 N s)^2 / (2 x 1.17^2) = 5.2e-3, past 1e-3.
  expect_advice(1.17, 1e-6, SimSettings{}, "a fine step: lower sim.refined_time_step");
}

TEST(SelfCheck, ALandingInACoarseStepAsksForTheCoarseStepItNeeds) {
  // A landing of 100 N s in a 1e-4 s step (sim.time_step, the fine step
  // 1e-6 s): bias (11.99 N s)^2 / (2 x 100^2) = 7.2e-3. Lowering the fine
  // step would not touch it; sim.time_step to 3.7e-5 s would.
  expect_advice(100.0, 1e-4, SimSettings{}, "a coarse step: lower sim.time_step");
}

TEST(SelfCheck, ALandingAtFixedStepsAsksForBothSettings) {
  // Fixed steps of 1e-5 s (sim.time_step = sim.refined_time_step): a 10 N s
  // landing needs 3.7e-6 s, below both; sim.refined_time_step may not
  // exceed sim.time_step, so both must go.
  SimSettings fixed;
  fixed.time_step_s = fixed.refined_time_step_s = 1e-5;
  expect_advice(10.0, 1e-5, fixed, "a coarse step: lower sim.time_step", "sim.refined_time_step with it");
}

TEST(SelfCheck, ALandingTheStepResolvesIsVouchedFor) {
  // 1.17 N s at 4e-7 s: bias 8.4e-4, under 1e-3.
  const SimVerdict v = inertial_self_check(run_with_landing(1.17, 4e-7), SimSettings{});
  EXPECT_TRUE(v.ok) << v.reason;
}

}  // namespace
}  // namespace railjoint
