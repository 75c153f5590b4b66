// One crossing per validation scene (scenes/validation/*.toml, the one
// validation set) at its own [sim] settings: building the Bullet world
// (meshes, BVH) and stepping through the impact, on one core. Target: under
// 50 ms per single-impact run. Then the inertial mode on the default scene
// (112.5 kN service load, rails as long as the predicted flight needs): a
// glued scenario-1 crossing, the scenario-2 strike with its 17 ms flight and
// landing, and the same strike with a compliant contact (fine steps through
// the whole contact).

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "scenes/scene_file.h"
#include "sim/crossing_model.h"
#include "sim/simulate_crossing.h"

namespace {

namespace fs = std::filesystem;

void BM_SimulateScene(benchmark::State& state, const railjoint::Scene& scene) {
  double error = 0.0;
  int steps = 0;
  for (auto _ : state) {
    const railjoint::SimulationResult r = railjoint::simulate_crossing(scene.joint, scene.wheel, scene.sim);
    benchmark::DoNotOptimize(r.impulse_Ns);
    error = (r.impulse_Ns - r.prediction.impulse.exact_Ns) / r.prediction.impulse.exact_Ns;
    steps = r.steps;
  }
  state.counters["error_vs_exact"] = error;
  state.counters["steps"] = steps;
}

void BM_Inertial(benchmark::State& state, railjoint::Scene scene, double lateral_m, bool compliant) {
  scene.wheel.lateral_m = lateral_m;
  scene.sim.mode = railjoint::SimMode::inertial;
  if (compliant) {
    scene.sim.run_out_time_s = 0.004;
    scene.sim.contact_stiffness_N_per_m = 1.5346e9;  // linearised Hertz at 112.5 kN + M g (impact_force_estimate.h)
  }
  scene.joint.length_m = std::max(scene.joint.length_m, railjoint::rail_length_needed_m(scene.joint, scene.wheel, scene.sim));
  int steps = 0;
  std::size_t impacts = 0;
  for (auto _ : state) {
    const railjoint::SimulationResult r = railjoint::simulate_crossing(scene.joint, scene.wheel, scene.sim);
    benchmark::DoNotOptimize(r.impulse_Ns);
    steps = r.steps;
    impacts = r.trajectory.impacts.size();
  }
  state.counters["steps"] = steps;
  state.counters["impacts"] = static_cast<double>(impacts);
}

// Registered from main: the scene reader's own statics must exist first.
void register_benchmarks() {
  const fs::path scenes = fs::path(RAILJOINT_SOURCE_DIR) / "scenes";
  std::vector<fs::path> files;
  for (const fs::directory_entry& e : fs::directory_iterator(scenes / "validation")) {
    if (e.path().extension() == ".toml") files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  for (const fs::path& file : files) {
    const railjoint::Scene scene = railjoint::load_scene(file.string());
    benchmark::RegisterBenchmark(("simulate_crossing/" + file.stem().string()).c_str(), BM_SimulateScene, scene)
        ->Unit(benchmark::kMillisecond);
  }
  const railjoint::Scene base = railjoint::load_scene((scenes / "default.toml").string());
  benchmark::RegisterBenchmark("inertial/scenario1_glued", BM_Inertial, base, 0.002, false)->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("inertial/scenario2_flight", BM_Inertial, base, 0.015, false)->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("inertial/scenario2_compliant", BM_Inertial, base, 0.015, true)->Unit(benchmark::kMillisecond);
}

}  // namespace

int main(int argc, char** argv) {
  register_benchmarks();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
