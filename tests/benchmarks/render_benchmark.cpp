// Frame cost of the off-screen renderer at 1280 x 720 (the target is below
// 50 ms a frame): drawing alone (GL draw + read-back), PNG encoding alone,
// both in sequence on one thread, and render_crossing's pipeline (rendering
// on the calling thread, encoding on a worker) measured per frame of wall time.
//
// The scene is the thesis's scenario-2 case (theta 30 deg, beta 0.03 rad,
// y_w = 15 mm, 50 m/s) with a 1 mm wide wheel (the simulation's stand-in for
// a thin disc): the wheel follows the kinematic path of the analytic model
// (no simulation needed to measure drawing). The render wheel has the sides
// the contact view needs (wheel_render_segments: 1,415 at 1280 px, 5,660
// triangles), the default contact view (0.12 m wide, heights x20).

#include <cmath>
#include <filesystem>

#include <benchmark/benchmark.h>

#include "geometry/rail_joint_mesh.h"
#include "geometry/wheel_mesh.h"
#include "models/impact_prediction.h"
#include "models/kinematic_trajectory.h"
#include "models/rail_top.h"
#include "renders/crossing_renderer.h"
#include "renders/png_file.h"
#include "renders/render_crossing.h"
#include "renders/wheel_tessellation.h"

namespace {

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

void BM_RenderFrame(benchmark::State& state) {
  const auto view = static_cast<RenderView>(state.range(0));
  CrossingRenderer renderer(hd(view), crossing().rails, crossing().wheel_mesh, crossing().trajectory);
  RgbImage image;
  long long k = 0;
  for (auto _ : state) {
    renderer.render_frame(k, image);
    k = (k + 1) % renderer.window().count;
    benchmark::DoNotOptimize(image.rgb.data());
  }
  state.SetLabel(to_string(view));
}
BENCHMARK(BM_RenderFrame)
    ->Arg(static_cast<int>(RenderView::side))
    ->Arg(static_cast<int>(RenderView::top))
    ->Arg(static_cast<int>(RenderView::perspective))
    ->Unit(benchmark::kMillisecond);

void BM_EncodePng(benchmark::State& state) {
  const auto view = static_cast<RenderView>(state.range(0));
  CrossingRenderer renderer(hd(view), crossing().rails, crossing().wheel_mesh, crossing().trajectory);
  RgbImage image;
  renderer.render_at(0.0, image);
  const auto path = std::filesystem::temp_directory_path() / "railjoint_render_benchmark.png";
  for (auto _ : state) write_png(path, image);
  state.counters["png_kB"] = static_cast<double>(std::filesystem::file_size(path)) / 1e3;
  state.SetLabel(to_string(view));
}
BENCHMARK(BM_EncodePng)
    ->Arg(static_cast<int>(RenderView::side))
    ->Arg(static_cast<int>(RenderView::perspective))
    ->Unit(benchmark::kMillisecond);

void BM_RenderAndEncodeSequential(benchmark::State& state) {
  CrossingRenderer renderer(hd(RenderView::side), crossing().rails, crossing().wheel_mesh, crossing().trajectory);
  RgbImage image;
  const auto path = std::filesystem::temp_directory_path() / "railjoint_render_benchmark.png";
  long long k = 0;
  for (auto _ : state) {
    renderer.render_frame(k, image);
    write_png(path, image);
    k = (k + 1) % renderer.window().count;
  }
}
BENCHMARK(BM_RenderAndEncodeSequential)->Unit(benchmark::kMillisecond);

// render_crossing over 41 frames (2 ms at 20000 fps): wall time per frame,
// with the context set-up and folder preparation included.
void BM_RenderCrossingPipelined(benchmark::State& state) {
  RenderSettings s = hd(RenderView::side);
  s.t_start_s = -1e-3;
  s.t_end_s = 1e-3;
  const auto out = std::filesystem::temp_directory_path() / "railjoint_render_benchmark_frames";
  RenderReport report;
  for (auto _ : state) {
    report = render_crossing(s, crossing().rails, crossing().wheel_mesh, crossing().trajectory, out);
  }
  state.counters["frames"] = static_cast<double>(report.frames_written);
  state.counters["wall_ms_per_frame"] = 1e3 * report.frames_wall_s / static_cast<double>(report.frames_written);
  state.counters["render_ms"] = report.render_ms_per_frame;
  state.counters["encode_ms"] = report.encode_ms_per_frame;
}
BENCHMARK(BM_RenderCrossingPipelined)->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace
