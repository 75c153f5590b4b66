// Where the time of an analytic sweep case goes (the target: >= 100,000
// cases per second per core, so the bookkeeping must cost less than the
// model): reading the case's scene from the base scene's parsed TOML tree
// with typed overrides, the kinematic prediction, formatting the row, and
// the whole row as the runner makes it.

#include <benchmark/benchmark.h>

#include "models/impact_prediction.h"
#include "scenes/report/csv_row.h"
#include "scenes/scene_tree.h"
#include "scenes/sweeps/case_evaluator.h"
#include "scenes/sweeps/case_models.h"
#include "scenes/sweeps/sweep_file.h"

namespace {

using namespace railjoint;

// 100 x 100 x 20 cases over the thesis's ranges, the analytic model only.
SweepFile analytic_sweep() {
  return parse_sweep_file(
      "base = \"" RAILJOINT_SOURCE_DIR "/scenes/default.toml\"\nrun = [\"analytic\"]\n[axes]\n"
      "\"joint.theta_deg\" = { from = 15.0, to = 90.0, count = 100 }\n"
      "\"wheel.y\" = { from = 0.0, to = 0.02, count = 100 }\n"
      "\"joint.beta\" = { from = 0.005, to = 0.05, count = 20 }\n",
      "benchmark.toml", std::nullopt, case_model_names());
}

void BM_CaseOverrides(benchmark::State& state) {
  const SweepFile sweep = analytic_sweep();
  const CaseGrid grid(sweep);
  std::vector<SceneOverride> overrides;
  std::uint64_t i = 0;
  for (auto _ : state) {
    grid.overrides(i++ % grid.size(), overrides);
    benchmark::DoNotOptimize(overrides.data());
  }
}
BENCHMARK(BM_CaseOverrides);

void BM_ReadSceneTree(benchmark::State& state) {
  const SweepFile sweep = analytic_sweep();
  const toml::table base = parse_scene_tree(sweep.base_text, sweep.base_scene);
  const CaseGrid grid(sweep);
  std::vector<SceneOverride> overrides;
  std::uint64_t i = 0;
  for (auto _ : state) {
    grid.overrides(i++ % grid.size(), overrides);
    const Scene scene = read_scene_tree(base, sweep.file, overrides, SceneCheck::geometry);
    benchmark::DoNotOptimize(scene.wheel.lateral_m);
  }
}
BENCHMARK(BM_ReadSceneTree);

void BM_PredictImpact(benchmark::State& state) {
  const SweepFile sweep = analytic_sweep();
  const toml::table base = parse_scene_tree(sweep.base_text, sweep.base_scene);
  const CaseGrid grid(sweep);
  std::vector<Scene> scenes;
  std::vector<SceneOverride> overrides;
  for (std::uint64_t i = 0; i < grid.size(); i += 97) {
    grid.overrides(i, overrides);
    scenes.push_back(read_scene_tree(base, sweep.file, overrides, SceneCheck::geometry));
  }
  std::size_t i = 0;
  for (auto _ : state) {
    const Scene& scene = scenes[i++ % scenes.size()];
    benchmark::DoNotOptimize(predict_impact(scene.joint, scene.wheel).impulse.exact_Ns);
  }
}
BENCHMARK(BM_PredictImpact);

void BM_FormatRow(benchmark::State& state) {
  CsvRow row;
  const double values[13] = {12345, 15.0, 0.0143, 0.03, 0.0041134664, 0.014, 0.0191612204, 0.0403503599,
                             2076.502428737095, 2075.1533885612075, 2075.638496008604, 1.0, 0.001};
  for (auto _ : state) {
    row.truncate(0, 0);
    for (double v : values) row.number(v);
    row.text("ok");
    row.end_line();
    benchmark::DoNotOptimize(row.str().data());
  }
}
BENCHMARK(BM_FormatRow);

void BM_AnalyticRow(benchmark::State& state) {
  const SweepFile sweep = analytic_sweep();
  const CaseEvaluator evaluator(sweep, case_models(sweep.models));
  CaseScratch scratch;
  CsvRow row;
  std::uint64_t i = 0;
  for (auto _ : state) {
    row.truncate(0, 0);
    evaluator.append_row(i++ % evaluator.grid().size(), scratch, row);
    benchmark::DoNotOptimize(row.str().data());
  }
}
BENCHMARK(BM_AnalyticRow);

}  // namespace

BENCHMARK_MAIN();
