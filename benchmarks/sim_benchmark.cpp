// One crossing per validation case at the default [sim] settings: building
// the Bullet world (meshes, BVH, internal-edge info) and stepping through
// the impact, on one core. Target: under 50 ms per single-impact run.

#include <benchmark/benchmark.h>

#include "sim/crossing_cases.h"
#include "sim/simulate_crossing.h"

namespace {

void BM_SimulateCrossing(benchmark::State& state, railjoint::CrossingCase crossing) {
  const railjoint::SimSettings settings;
  double error = 0.0;
  int steps = 0;
  for (auto _ : state) {
    const railjoint::SimulationResult r = railjoint::simulate_crossing(crossing.joint, crossing.wheel, settings);
    benchmark::DoNotOptimize(r.impulse_Ns);
    error = (r.impulse_Ns - r.prediction.impulse.exact_Ns) / r.prediction.impulse.exact_Ns;
    steps = r.steps;
  }
  state.counters["error_exact_percent"] = 100.0 * error;
  state.counters["steps"] = steps;
}

const bool registered = [] {
  for (const railjoint::CrossingCase& c : railjoint::validation_crossings()) {
    benchmark::RegisterBenchmark(("simulate_crossing/" + c.name).c_str(), BM_SimulateCrossing, c)
        ->Unit(benchmark::kMillisecond);
  }
  return true;
}();

}  // namespace

BENCHMARK_MAIN();
