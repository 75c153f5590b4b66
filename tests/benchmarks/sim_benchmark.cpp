// One crossing per validation case at the default [sim] settings: building
// the Bullet world (meshes, BVH, internal-edge info) and stepping through
// the impact, on one core. Target: under 50 ms per single-impact run.
// Then the inertial mode (3 m joint, 112.5 kN): a glued scenario-1 crossing,
// a scenario-2 strike with its 16 ms flight and landing, and the same strike
// with a compliant contact (fine steps through the whole contact).

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

void BM_InertialCrossing(benchmark::State& state, railjoint::CrossingCase crossing, bool compliant) {
  crossing.joint.length_m = 3.0;
  railjoint::SimSettings settings;
  settings.mode = railjoint::SimMode::inertial;
  settings.run_out_time_s = 0.02;
  if (compliant) {
    settings.run_out_time_s = 0.004;
    settings.contact_stiffness_N_per_m = 1.5346e9;  // linearised Hertz at 112.5 kN + M g (impact_force_estimate.h)
  }
  int steps = 0;
  std::size_t impacts = 0;
  for (auto _ : state) {
    const railjoint::SimulationResult r = railjoint::simulate_crossing(crossing.joint, crossing.wheel, settings);
    benchmark::DoNotOptimize(r.impulse_Ns);
    steps = r.steps;
    impacts = r.trajectory.impacts.size();
  }
  state.counters["steps"] = steps;
  state.counters["impacts"] = static_cast<double>(impacts);
}

const bool registered = [] {
  for (const railjoint::CrossingCase& c : railjoint::validation_crossings()) {
    benchmark::RegisterBenchmark(("simulate_crossing/" + c.name).c_str(), BM_SimulateCrossing, c)
        ->Unit(benchmark::kMillisecond);
  }
  benchmark::RegisterBenchmark("inertial/scenario1_theta45_glued", BM_InertialCrossing,
                               railjoint::inclined_crossing("s1", 45.0, 0.002), false)
      ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("inertial/scenario2_theta30_flight", BM_InertialCrossing,
                               railjoint::inclined_crossing("s2", 30.0, 0.015), false)
      ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("inertial/scenario2_theta30_compliant", BM_InertialCrossing,
                               railjoint::inclined_crossing("s2", 30.0, 0.015), true)
      ->Unit(benchmark::kMillisecond);
  return true;
}();

}  // namespace

BENCHMARK_MAIN();
