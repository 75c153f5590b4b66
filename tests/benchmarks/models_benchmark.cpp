// Cost of the analytic model: it is called once per simulated scene and
// thousands of times in sweeps, so it must stay far below the simulation.

#include <benchmark/benchmark.h>

#include "models/impact_prediction.h"
#include "models/time_history.h"

namespace {

void BM_PredictScenario2(benchmark::State& state) {
  railjoint::JointParams joint;
  railjoint::WheelParams wheel;  // thesis fig. 4.5 point: scenario 2
  for (auto _ : state) benchmark::DoNotOptimize(railjoint::predict_impact(joint, wheel));
}
BENCHMARK(BM_PredictScenario2);

// The general model (models/wheel_rail_envelope.h): a 1:40 cone on a 300 mm
// crown, thin disc and a tread wider than the head (the target:
// above 50,000 cases per second per core, 20 us a case), and a curved dip.
void BM_PredictCrownAndCone(benchmark::State& state) {
  railjoint::JointParams joint;
  joint.crown_radius_m = 0.3;
  railjoint::WheelParams wheel;
  wheel.conicity = 0.025;
  wheel.width_m = static_cast<double>(state.range(0)) * 1e-3;
  wheel.lateral_m = 0.0;
  for (auto _ : state) benchmark::DoNotOptimize(railjoint::predict_impact(joint, wheel));
}
BENCHMARK(BM_PredictCrownAndCone)->Arg(0)->Arg(70);

void BM_PredictCosineDip(benchmark::State& state) {
  railjoint::JointParams joint;
  joint.dip_shape = railjoint::DipShape::cosine;
  railjoint::WheelParams wheel;
  for (auto _ : state) benchmark::DoNotOptimize(railjoint::predict_impact(joint, wheel));
}
BENCHMARK(BM_PredictCosineDip);

void BM_TimeHistory2001(benchmark::State& state) {
  railjoint::JointParams joint;
  railjoint::WheelParams wheel;
  for (auto _ : state) benchmark::DoNotOptimize(railjoint::impact_time_history(joint, wheel, 2e-4, 2.4e-4, 2001));
}
BENCHMARK(BM_TimeHistory2001);

}  // namespace
