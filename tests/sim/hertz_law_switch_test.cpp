// A force run whose contact changes Hertz's law under load (elastic_crossing_run.cpp,
// law_switch_within): on 60E1 under a 1:40 cone, 70 mm wide, at an inclined
// cut the incoming rail's touching point runs off its face onto the rail
// end's cut edge while it bears, and G steps from the face's elliptical
// constant to the edge's empirical one (4.80e-8 to 4.21e-8 m/N^(2/3)): the
// force at a given penetration jumps by (4.80 / 4.21)^(3/2) = 1.22. A step
// across that jump made P1 converge at first order (every step at 1e-6,
// 0.5e-6, 0.25e-6 s: 548007.8, 548034.2, 548047.0 N at 35 deg, ratio 2.06;
// at 20 deg not even monotone). Located, the run is velocity Verlet's again:
// second order, and P1 at the default step within the 1e-5 of the
// converged value.
//
// The reference is outside the code under test's default: Richardson's
// extrapolation (4 P(h/2) - P(h)) / 3 from runs with every step at 0.5e-6
// and 0.25e-6 s, whose own error is O(h^3) (measured: it moves by 1e-3 N
// when the pair is halved again, 2e-9 of P1). The runs end 1.5 ms after the
// impact (P1 is at about 0.8 ms after it; the value is the full run's to the
// last digit): the P2 part is not what is tested and would cost 10x.

#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "models/wheel_rail_envelope.h"
#include "sim/crossing_model.h"
#include "sim/simulate_crossing.h"

namespace railjoint {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct Case {
  double theta_deg;
  double lateral_m;
};

JointParams joint_of(const Case& c) {
  JointParams joint;
  joint.theta_rad = c.theta_deg * kPi / 180.0;
  joint.beta_rad = 0.03;
  joint.half_width_m = 0.036;
  joint.rail_profile = RailProfile::en_60e1;
  return joint;
}

WheelParams wheel_of(const Case& c) {
  WheelParams wheel;
  wheel.width_m = 0.07;
  wheel.lateral_m = c.lateral_m;
  wheel.conicity = 0.025;
  wheel.speed_m_per_s = 50.0;
  return wheel;
}

// `every_step`: every step at `step_s` (sim.refined_time_step too); else the
// default stepping, the impact's pulse at 1e-6 s.
ForceOutcome lumped_run(const Case& c, double step_s, bool every_step) {
  SimSettings s;
  if (every_step) s.refined_time_step_s = step_s;
  ElasticCrossingSettings& e = s.make_inertial().contact.emplace<ElasticCrossingSettings>();
  e.track.emplace();
  s.make_inertial().force_time_step_s = step_s;
  s.run_out_time_s = 1.5e-3;
  JointParams joint = joint_of(c);
  const WheelParams wheel = wheel_of(c);
  joint.length_m = std::max(1.0, rail_length_needed_m(joint, wheel, s));
  return *simulate_crossing(joint, wheel, s).inertial()->forces;
}

void expect_second_order_and_within_1e5(const Case& c) {
  // The case does switch: the cone touches the head at y = -7.5 mm, where
  // the cut lies at x = y cot(theta) (-10.7 mm at 35 deg, -20.6 mm at 20);
  // the incoming rail's touching point sits R beta / 2 = 7 mm ahead of the
  // wheel's centre on the face: on the face with the centre at -50 mm, on
  // the edge at +10 mm (the models' own envelope, no force run).
  const WheelParams wheel = wheel_of(c);
  const JointParams joint = joint_of(c);
  EXPECT_FALSE(rail_support(joint, wheel, 0, -0.05).at_cut_edge);
  EXPECT_TRUE(rail_support(joint, wheel, 0, 0.01).at_cut_edge);

  const double coarse_N = lumped_run(c, 1e-6, true).p1_N;
  const double fine_N = lumped_run(c, 0.5e-6, true).p1_N;
  const double finer_N = lumped_run(c, 0.25e-6, true).p1_N;
  const double reference_N = (4.0 * finer_N - fine_N) / 3.0;
  const double default_N = lumped_run(c, 4e-6, false).p1_N;
  const double ratio = (coarse_N - fine_N) / (fine_N - finer_N);
  std::printf("theta %.0f deg, y_w %.3f m: P1 every step at 1e-6, 0.5e-6, 0.25e-6 s %.2f, %.2f, %.2f N (ratio %.2f); "
              "Richardson %.2f N; default step %.2f N (%+.2e)\n",
              c.theta_deg, c.lateral_m, coarse_N, fine_N, finer_N, ratio, reference_N, default_N,
              default_N / reference_N - 1.0);
  // Second order halves the step's error 4 times (measured 3.96); a step
  // across the switch left a first-order term, ratio 2 or erratic.
  EXPECT_GT(ratio, 3.0);
  EXPECT_LT(ratio, 5.0);
  // The bound. What is left at the default step is Verlet's phase
  // error of the rail's ringing at 1e-6 s, (w dt)^2 / 24 ~ 3e-6 at w ~ 8.5e3
  // rad/s (measured -4.1e-6, as on the flat head's -4.4e-6).
  EXPECT_NEAR(default_N / reference_N, 1.0, 1e-5);
}

TEST(HertzLawSwitch, P1ConvergesAtSecondOrderWhereTheWheelSpans60E1sInclinedCut) {
  expect_second_order_and_within_1e5({35.0, 0.0});
}

TEST(HertzLawSwitch, P1ConvergesAtSecondOrderAtAShallowerCutAndAnotherOffset) {
  expect_second_order_and_within_1e5({20.0, 0.01});
}

}  // namespace
}  // namespace railjoint
