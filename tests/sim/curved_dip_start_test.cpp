// Where a force run on a curved dip starts (issue 37): on the level rail
// before the dip bends, where its static state is an equilibrium. Started
// inside the bend (sim.approach_distance before the impact, the old start),
// the path's curvature z'' loaded the contact by M v^2 z'' from the first
// step and the run's own static-equilibrium check marked it suspect (3 % of
// P0 on a 0.3 m cosine dip at 50 m/s). Expected values here are invariants:
// on a level rail the static state holds the contact force at P0 to
// round-off; a start further back on that rail changes nothing but the step's
// phase; and the check still fails a start that is not static.

#include <cmath>
#include <memory>

#include <gtest/gtest.h>

#include "models/kinematic_trajectory.h"
#include "sim/crossing_model.h"
#include "sim/setting_checks.h"
#include "sim/simulate_crossing.h"

namespace railjoint {
namespace {

constexpr double kDipLength_m = 0.3;

SimSettings lumped_hertz_settings(double approach_m) {
  SimSettings s;
  s.make_inertial().contact.emplace<ElasticCrossingSettings>().track.emplace();
  s.approach_distance_m = approach_m;
  return s;
}

// The lumped scene (scenes/forces/lumped_track.toml: square joint, beta
// 0.03, thin disc, 50 m/s) on a cosine dip of 0.3 m.
JointParams cosine_dip() {
  JointParams joint;
  joint.theta_rad = std::acos(0.0);
  joint.beta_rad = 0.03;
  joint.dip_shape = DipShape::cosine;
  joint.dip_length_m = kDipLength_m;
  return joint;
}

WheelParams thin_disc(double speed_m_per_s) {
  WheelParams wheel;
  wheel.width_m = 0.0;
  wheel.speed_m_per_s = speed_m_per_s;
  return wheel;
}

std::shared_ptr<CrossingModel> model_of(const SimSettings& settings, double speed_m_per_s = 50.0) {
  JointParams joint = cosine_dip();
  const WheelParams wheel = thin_disc(speed_m_per_s);
  joint.length_m = std::max(1.0, rail_length_needed_m(joint, wheel, settings));
  return std::make_shared<CrossingModel>(build_crossing_model(joint, wheel, settings));
}

bool static_check_failed(const SimulationResult& r) {
  return r.verdict.reason.find("not in static equilibrium") != std::string::npos;
}

TEST(CurvedDipStart, AForceRunStartsOnTheLevelRailInStaticEquilibrium) {
  const auto model = model_of(lumped_hertz_settings(0.05));
  // The bend begins where the contact, under the centre on the level rail,
  // reaches x = -D; the start lies sim.approach_distance before that.
  EXPECT_NEAR(model->start.centre_m.x(), -kDipLength_m - 0.05, 1e-12);
  EXPECT_EQ(model->start.vertical_velocity_m_per_s, 0.0);
  const SimulationResult r = simulate_crossing(model);
  const ForceOutcome& f = *r.inertial()->forces;
  // On the level rail the static state is an equilibrium: the force is P0
  // to round-off (1e-9: the force's ~1e-16 relative rounding grown by the
  // steps and the Hertz power) until the contact enters the bend.
  double worst = 0.0;
  std::size_t on_straight = 0;
  // (Sample 0 is the start's state, before any step: no force recorded.)
  for (std::size_t k = 1; k < r.trajectory.samples.size(); ++k) {
    if (r.trajectory.samples[k].centre_m.x() >= -kDipLength_m - 1e-6) break;
    worst = std::max(worst, std::abs(f.contact_force_N[k] - f.static_N) / f.static_N);
    ++on_straight;
  }
  EXPECT_GT(on_straight, 200u);  // 0.05 m at 50 m/s in 4 us steps: 250
  EXPECT_LT(worst, 1e-9);
  EXPECT_FALSE(static_check_failed(r)) << r.verdict.reason;
}

TEST(CurvedDipStart, P1AndP2DoNotDependOnHowFarBackOnTheLevelItStarts) {
  // 0.05 and 0.1373 m: not a whole number of steps apart, so the impact
  // falls at another phase of the step. From a static start on the level
  // rail the runs differ only by that phase (half the step moves P1 by
  // ~1e-5 on these tracks, docs/forces.md): 1e-4 is a tenth of the 0.1 %
  // the issue asks.
  const SimulationResult near = simulate_crossing(model_of(lumped_hertz_settings(0.05)));
  const SimulationResult far = simulate_crossing(model_of(lumped_hertz_settings(0.1373)));
  const ForceOutcome& a = *near.inertial()->forces;
  const ForceOutcome& b = *far.inertial()->forces;
  EXPECT_NEAR(b.p1_N / a.p1_N, 1.0, 1e-4);
  ASSERT_TRUE(a.p2 && b.p2);
  EXPECT_NEAR(b.p2->force_N / a.p2->force_N, 1.0, 1e-4);
}

TEST(CurvedDipStart, TheCheckStillFailsAStartInsideTheBend) {
  // The old start: sim.approach_distance before the predicted impact, on
  // the kinematic path there with its slope's velocity, sunk by the static
  // load as if the rail were straight. The bend then loads the contact by
  // M v^2 z'' (z'' = -t k sin(k s), k = pi / 2D, s = 5 cm: 750 kg x 2500 x
  // 0.020 / m = 38 kN, before the track's share), far past the check's 1e-3.
  auto model = model_of(lumped_hertz_settings(0.05));
  const double v = model->wheel.speed_m_per_s;
  const double x0 = model->prediction.impact_wheel_x_m - 0.05;
  model->start.centre_m.x() = x0;
  model->start.centre_m.z() = kinematic_centre_height_m(model->joint, model->simulated_wheel, x0) - model->static_sink_m;
  model->start.vertical_velocity_m_per_s = v * kinematic_centre_slope(model->joint, model->simulated_wheel, x0, +1);
  model->end_time_s = 0.05 / v + model->run_out_time_s;
  const SimulationResult r = simulate_crossing(model);
  EXPECT_TRUE(static_check_failed(r)) << r.verdict.reason;
}

TEST(CurvedDipStart, TheCheckStillFailsAWrongStaticStateOnTheLevel) {
  // On the level rail but 1 um too deep: Hertz's force at 103.2 um against
  // 102.2 um is 1.5 % above P0, the check's 1e-3 fifteen times over.
  auto model = model_of(lumped_hertz_settings(0.05));
  model->start.centre_m.z() -= 1e-6;
  const SimulationResult r = simulate_crossing(model);
  EXPECT_TRUE(static_check_failed(r)) << r.verdict.reason;
}

// A step down (0.5 mm, lumped track, 50 m/s, thin disc): the wheel pivots
// over the incoming rail's edge (x = 0) before it lands on the lower rail,
// which the prediction puts 22 mm on. The static check ran to 20 mm before
// the landing, over the pivot, where the force falls (the path bends by
// -1 / R): 4.9 % of P0, suspect. The approach is straight up to the edge,
// and the run starts sim.approach_distance before it.
TEST(StepDownStart, AStepDownStartsBeforeTheEdgeAndItsApproachIsStatic) {
  JointParams joint;
  joint.kind = JointKind::step;
  joint.step_height_m = -5e-4;
  const WheelParams wheel = thin_disc(50.0);
  const SimSettings settings = lumped_hertz_settings(0.05);
  joint.length_m = std::max(1.0, rail_length_needed_m(joint, wheel, settings));
  const auto model = std::make_shared<CrossingModel>(build_crossing_model(joint, wheel, settings));
  EXPECT_NEAR(model->start.centre_m.x(), -0.05, 1e-12);
  const SimulationResult r = simulate_crossing(model);
  EXPECT_FALSE(static_check_failed(r)) << r.verdict.reason;
}

}  // namespace
}  // namespace railjoint
