// Speed of the local contact-pressure model (models/pressure_traversal.h) on
// table 6.1: a 1000-step exact traversal (target < 1 ms), its summary (the
// refined maxima and the five points), the figure-6.5/6.6 sweep over 100
// junction angles (target < 0.1 s), and the thesis's polygon mode through
// Boost.Geometry for comparison.

#include <numbers>

#include <benchmark/benchmark.h>

#include "models/pressure_traversal.h"

namespace {

using namespace railjoint;

PressureInputs table_6_1(PatchShape shape = PatchShape::ellipse) {
  PressureInputs in;
  in.patch = ContactPatch{shape, 0.016, 0.012, 100};
  in.gap = EndPostGap{0.006, std::numbers::pi / 6.0};
  in.steps = 1000;
  return in;
}

void BM_ExactTraversal1000Steps(benchmark::State& state) {
  const PressureInputs in = table_6_1();
  for (auto _ : state) benchmark::DoNotOptimize(pressure_traversal(in));
}
BENCHMARK(BM_ExactTraversal1000Steps)->Unit(benchmark::kMicrosecond);

void BM_ExactTraversalAndSummary(benchmark::State& state) {
  const PressureInputs in = table_6_1();
  for (auto _ : state) {
    const auto traversal = pressure_traversal(in);
    benchmark::DoNotOptimize(summarize_pressure(in, traversal));
  }
}
BENCHMARK(BM_ExactTraversalAndSummary)->Unit(benchmark::kMicrosecond);

void BM_ThetaSweep100Angles(benchmark::State& state) {
  const PressureInputs in = table_6_1();
  for (auto _ : state) benchmark::DoNotOptimize(theta_sweep(in, 1.0, 90.0, 100));
}
BENCHMARK(BM_ThetaSweep100Angles)->Unit(benchmark::kMillisecond);

void BM_PolygonTraversal1000Steps(benchmark::State& state) {
  const PressureInputs in = table_6_1(PatchShape::polygon);
  for (auto _ : state) benchmark::DoNotOptimize(pressure_traversal(in));
}
BENCHMARK(BM_PolygonTraversal1000Steps)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
