// One crossing per validation scene (scenes/validation/*.toml, the one
// validation set) at its own [sim] settings: building the Bullet world
// (meshes, BVH) and stepping through the impact, on one core. Target: under
// 50 ms per single-impact run. Then the inertial mode on the default scene
// (112.5 kN service load, rails as long as the predicted flight needs): a
// glued scenario-1 crossing, the scenario-2 strike with its 17 ms flight and
// landing, and the same strike with a compliant contact (fine steps through
// the whole contact). Last, force runs (Hertz contact) on the lumped track of
// scenes/forces/lumped_track.toml at 50 m/s, square and scenario 2, and on a
// rigid track: target under 20 ms of CPU each; and on the discrete track
// (scenes/forces/discrete_track.toml): target under 200 ms. A bogie there
// (scenes/forces/bogie.toml: two wheels 2.5 m apart, a run 50 ms longer on
// a longer track): target within 5x of the single wheel's discrete_square_50.

#include <algorithm>
#include <filesystem>
#include <limits>
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
    benchmark::DoNotOptimize(r.impulse_Ns());
    error = (r.impulse_Ns() - r.prediction().impulse.exact_Ns) / r.prediction().impulse.exact_Ns;
    steps = r.steps;
  }
  state.counters["error_vs_exact"] = error;
  state.counters["steps"] = steps;
}

void BM_Inertial(benchmark::State& state, railjoint::Scene scene, double lateral_m, bool compliant) {
  scene.wheel.lateral_m = lateral_m;
  scene.sim.make_inertial();
  if (compliant) {
    scene.sim.run_out_time_s = 0.004;
    scene.sim.make_inertial().contact.emplace<railjoint::LinearContactSettings>().stiffness_N_per_m =
        1.5346e9;  // linearised Hertz at 112.5 kN + M g (impact_force_estimate.h)
  }
  scene.joint.length_m = std::max(scene.joint.length_m, railjoint::rail_length_needed_m(scene.joint, scene.wheel, scene.sim));
  int steps = 0;
  std::size_t impacts = 0;
  for (auto _ : state) {
    const railjoint::SimulationResult r = railjoint::simulate_crossing(scene.joint, scene.wheel, scene.sim);
    benchmark::DoNotOptimize(r.impulse_Ns());
    steps = r.steps;
    impacts = r.trajectory.impacts.size();
  }
  state.counters["steps"] = steps;
  state.counters["impacts"] = static_cast<double>(impacts);
}

void BM_ForceRun(benchmark::State& state, railjoint::Scene scene, double theta_deg, double lateral_m, bool elastic) {
  scene.joint.theta_rad = theta_deg * 3.14159265358979323846 / 180.0;
  scene.wheel.lateral_m = lateral_m;
  if (!elastic) scene.sim.elastic()->track.reset();
  scene.joint.length_m = std::max(1.0, railjoint::rail_length_needed_m(scene.joint, scene.wheel, scene.sim));
  double p1_N = 0.0, p2_N = 0.0;
  int steps = 0;
  for (auto _ : state) {
    const railjoint::SimulationResult r = railjoint::simulate_crossing(scene.joint, scene.wheel, scene.sim);
    benchmark::DoNotOptimize(r.impulse_Ns());
    p1_N = r.inertial()->forces->p1_N;
    const auto& p2 = r.inertial()->forces->p2;  // none on a rigid track
    p2_N = p2 ? p2->force_N : std::numeric_limits<double>::quiet_NaN();
    steps = r.steps;
  }
  state.counters["p1_kN"] = p1_N / 1e3;
  state.counters["p2_kN"] = p2_N / 1e3;
  state.counters["steps"] = steps;
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
  // The README's scene, against which a Python call's overhead is measured (scripts/benchmarks/python_overhead.py).
  benchmark::RegisterBenchmark("simulate_crossing/default", BM_SimulateScene, base)->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("inertial/scenario1_glued", BM_Inertial, base, 0.002, false)->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("inertial/scenario2_flight", BM_Inertial, base, 0.015, false)->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("inertial/scenario2_compliant", BM_Inertial, base, 0.015, true)->Unit(benchmark::kMillisecond);
  const railjoint::Scene forces = railjoint::load_scene((scenes / "forces" / "lumped_track.toml").string());
  benchmark::RegisterBenchmark("forces/lumped_square_50", BM_ForceRun, forces, 90.0, 0.0, true)->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("forces/lumped_scenario2_50", BM_ForceRun, forces, 45.0, 0.01, true)
      ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("forces/rigid_track_square_50", BM_ForceRun, forces, 90.0, 0.0, false)
      ->Unit(benchmark::kMillisecond);
  const railjoint::Scene discrete = railjoint::load_scene((scenes / "forces" / "discrete_track.toml").string());
  benchmark::RegisterBenchmark("forces/discrete_square_50", BM_ForceRun, discrete, 90.0, 0.0, true)
      ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("forces/discrete_scenario2_50", BM_ForceRun, discrete, 45.0, 0.01, true)
      ->Unit(benchmark::kMillisecond);
  // Issue 37's real geometry: 60E1 under a 1:40 cone, the contact's point,
  // normal and Hertz's elliptical constant found at every step (targets: within
  // 2x of the flat head's lumped run, 3x of its discrete run).
  const std::vector<std::string> on_60e1 = {"joint.rail_profile=60E1", "joint.half_width=0.036",
                                             "wheel.conicity=0.025", "wheel.width=0.07"};
  const railjoint::Scene lumped_60e1 = railjoint::load_scene((scenes / "forces" / "lumped_track.toml").string(), on_60e1);
  const railjoint::Scene discrete_60e1 =
      railjoint::load_scene((scenes / "forces" / "discrete_track.toml").string(), on_60e1);
  benchmark::RegisterBenchmark("forces/lumped_60e1_cone_square_50", BM_ForceRun, lumped_60e1, 90.0, 0.0, true)
      ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("forces/discrete_60e1_cone_square_50", BM_ForceRun, discrete_60e1, 90.0, 0.0, true)
      ->Unit(benchmark::kMillisecond);
  const railjoint::Scene bogie = railjoint::load_scene((scenes / "forces" / "bogie.toml").string());
  benchmark::RegisterBenchmark("forces/discrete_bogie_square_50", BM_ForceRun, bogie, 90.0, 0.0, true)
      ->Unit(benchmark::kMillisecond);
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
