// Frame cost of the off-screen renderer at 1280 x 720 (the target: a written
// frame, drawn and encoded, in under 10 ms): drawing alone (GL draw,
// read-back, anti-aliasing) per view, back end and anti-aliasing; PNG
// encoding alone per encoder setting; and render_crossing's pipeline (drawing
// on the calling thread, two encoder threads) as wall time per written frame
// and frames per second. Times are wall clock ("Time") and the whole
// process's CPU, llvmpipe's threads included ("CPU"): on a loaded machine the
// CPU column is the steadier one.
//
// The scene is the thesis's scenario-2 case (theta 30 deg, beta 0.03 rad,
// y_w = 15 mm, 50 m/s) with a 1 mm wide wheel (the simulation's stand-in for
// a thin disc): the wheel follows the kinematic path of the analytic model
// (no simulation needed to measure drawing). The render wheel has the sides
// the contact view needs (wheel_render_segments: 1,415 at 1280 px, 5,660
// triangles), the default contact view (0.12 m wide, heights x20).

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

#include <benchmark/benchmark.h>

#include "geometry/rail_joint_mesh.h"
#include "geometry/wheel_mesh.h"
#include "models/impact_prediction.h"
#include "models/kinematic_trajectory.h"
#include "models/rail_top.h"
#include "renders/crossing_view.h"
#include "renders/fxaa.h"
#include "renders/png_file.h"
#include "renders/render_crossing.h"
#include "renders/wheel_tessellation.h"

namespace {

// A folder of this run's own (two runs at once must not write the same files).
std::filesystem::path benchmark_dir() {
  static const std::filesystem::path dir = [] {
    std::string pattern = (std::filesystem::temp_directory_path() / "railjoint_render_benchmark_XXXXXX").string();
    return std::filesystem::path(mkdtemp(pattern.data()) != nullptr ? pattern : std::string("."));
  }();
  return dir;
}

using namespace railjoint;

WheelParams thin_wheel() {
  WheelParams w;
  w.width_m = 0.001;
  return w;
}

struct CrossingCase {
  JointParams joint;
  WheelParams wheel;
  RailJointMesh rails;
  TriangleMesh wheel_mesh;
  Trajectory trajectory;  // 2 ms around the impact, samples every 1 us

  CrossingCase()
      : wheel(thin_wheel()),
        rails(build_rail_joint_mesh(joint)),
        wheel_mesh(build_wheel_mesh(wheel, wheel_render_segments(RenderSettings{}, wheel.radius_m), 0.0)) {
    const ImpactPrediction impact = predict_impact(joint, wheel);
    const double v = wheel.speed_m_per_s;
    for (int i = 0; i <= 2000; ++i) {
      const double t = -1e-3 + i * 1e-6;
      const double x = impact.impact_wheel_x_m + v * t;
      WheelSample s;
      s.time_s = t;
      s.centre_m = {x, wheel.lateral_m, kinematic_centre_height_m(joint, wheel, x)};
      s.velocity_m_per_s = {v, 0.0, 0.0};
      s.spin_angle_rad = v * (t + 1e-3) / wheel.radius_m;
      ContactSample contact;
      contact.point_on_rail_m = t < 0 ? Eigen::Vector3d(x, wheel.lateral_m, rail_top_height_m(joint, x, wheel.lateral_m))
                                      : impact.contact_A_m;
      s.contacts.push_back(contact);
      trajectory.samples.push_back(s);
    }
    trajectory.impacts.push_back({0.0, impact.impact_wheel_x_m, impact.impulse.exact_Ns, impact.contact_A_m});
  }
};

RenderSettings hd(RenderView view) {
  RenderSettings s;
  s.width_px = 1280;
  s.height_px = 720;
  s.view = view;
  s.fps = 20000;
  s.ffmpeg = false;
  return s;
}

const CrossingCase& crossing() {
  static const CrossingCase c;
  return c;
}

// Drawing one frame: per view, with the default anti-aliasing (FXAA).
void BM_DrawFrame(benchmark::State& state) {
  const auto view = static_cast<RenderView>(state.range(0));
  const auto renderer = CrossingView::make(hd(view), crossing().rails, crossing().wheel_mesh, crossing().trajectory);
  RgbImage image;
  long long k = 0;
  for (auto _ : state) {
    renderer->render_at(renderer->window().time_s(k), image);
    k = (k + 1) % renderer->window().count;
    benchmark::DoNotOptimize(image.rgb.data());
  }
  state.SetLabel(to_string(view));
}
BENCHMARK(BM_DrawFrame)
    ->DenseRange(0, 2)
    ->MeasureProcessCPUTime()
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

// What each anti-aliasing costs: none, FXAA on the CPU, 4x multisampling.
void BM_DrawFrameAntialiasing(benchmark::State& state) {
  const auto view = static_cast<RenderView>(state.range(0));
  RenderSettings settings = hd(view);
  settings.antialiasing = static_cast<Antialiasing>(state.range(1));
  const auto renderer = CrossingView::make(settings, crossing().rails, crossing().wheel_mesh, crossing().trajectory);
  RgbImage image;
  long long k = 0;
  for (auto _ : state) {
    renderer->render_at(renderer->window().time_s(k), image);
    k = (k + 1) % renderer->window().count;
    benchmark::DoNotOptimize(image.rgb.data());
  }
  state.SetLabel(std::string(to_string(view)) + " " + to_string(settings.antialiasing));
}
BENCHMARK(BM_DrawFrameAntialiasing)
    ->ArgsProduct({{0, 1, 2}, {0, 1, 2}})
    ->MeasureProcessCPUTime()
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

// FXAA alone on a drawn frame (drawn without anti-aliasing), one thread.
void BM_Fxaa(benchmark::State& state) {
  const auto view = static_cast<RenderView>(state.range(0));
  RenderSettings settings = hd(view);
  settings.antialiasing = Antialiasing::none;
  const auto renderer = CrossingView::make(settings, crossing().rails, crossing().wheel_mesh, crossing().trajectory);
  RgbImage drawn;
  renderer->render_at(0.0, drawn);
  for (auto _ : state) {
    RgbImage image = drawn;
    apply_fxaa(image);
    benchmark::DoNotOptimize(image.rgb.data());
  }
  state.SetLabel(to_string(view));
}
BENCHMARK(BM_Fxaa)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);

// Encoding one frame into its file: libpng with zlib level 1, no row filter.
void BM_EncodePng(benchmark::State& state) {
  const auto view = static_cast<RenderView>(state.range(0));
  const auto renderer = CrossingView::make(hd(view), crossing().rails, crossing().wheel_mesh, crossing().trajectory);
  RgbImage image;
  renderer->render_at(0.0, image);
  const std::filesystem::path file = benchmark_dir() / "encoded.png";
  for (auto _ : state) write_png(file, image);
  state.counters["png_kB"] = static_cast<double>(std::filesystem::file_size(file)) / 1e3;
  state.SetLabel(to_string(view));
}
BENCHMARK(BM_EncodePng)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);

// A written frame: render_crossing over 101 frames (2 ms at 50000 fps), PNG
// files only (no videos, no glTF), per view: wall time per frame
// from the first frame drawn to the last file written, and frames per second;
// mean times per frame of drawing (calling thread), finishing (FXAA, labels)
// and encoding (the two workers).
void BM_WrittenFrame(benchmark::State& state) {
  const auto view = static_cast<RenderView>(state.range(0));
  RenderSettings s = hd(view);
  s.fps = 50000;
  s.t_start_s = -1e-3;
  s.t_end_s = 1e-3;
  s.gltf = false;
  const auto out = benchmark_dir() / "frames";
  RenderReport report;
  for (auto _ : state) {
    report = render_crossing(s, crossing().rails, crossing().wheel_mesh, crossing().trajectory, out);
  }
  const double wall_ms = 1e3 * report.frames_wall_s / static_cast<double>(report.frames_written);
  state.counters["frames"] = static_cast<double>(report.frames_written);
  state.counters["wall_ms_per_frame"] = wall_ms;
  state.counters["fps"] = 1e3 / wall_ms;
  state.counters["draw_ms"] = report.render_ms_per_frame;
  state.counters["finish_ms"] = report.finish_ms_per_frame;
  state.counters["encode_ms"] = report.encode_ms_per_frame;
  state.SetLabel(to_string(view));
}
BENCHMARK(BM_WrittenFrame)
    ->DenseRange(0, 2)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);

}  // namespace
