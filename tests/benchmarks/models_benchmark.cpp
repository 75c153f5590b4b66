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

void BM_TimeHistory2001(benchmark::State& state) {
  railjoint::JointParams joint;
  railjoint::WheelParams wheel;
  for (auto _ : state) benchmark::DoNotOptimize(railjoint::impact_time_history(joint, wheel, 2e-4, 2.4e-4, 2001));
}
BENCHMARK(BM_TimeHistory2001);

}  // namespace
