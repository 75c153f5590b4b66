#include "renders/render_crossing.h"

#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>
#include <stdexcept>
#include <system_error>

#include "renders/crossing_gltf.h"
#include "renders/crossing_view.h"
#include "renders/perspective_view.h"
#include "renders/png_file.h"
#include "renders/top_view.h"
#include "renders/video_assembly.h"

namespace railjoint {

namespace {

void prepare_output_folder(const std::filesystem::path& out_dir) {
  std::error_code ec;
  std::filesystem::create_directories(out_dir, ec);
  if (ec || !std::filesystem::is_directory(out_dir)) {
    throw std::runtime_error("render: cannot create the output folder '" + out_dir.string() +
                             "': " + (ec ? ec.message() : "a file of that name exists"));
  }
}

}  // namespace

std::string frame_file_name(long long k) {
  char name[32];
  std::snprintf(name, sizeof(name), "frame_%05lld.png", k);
  return name;
}

RenderReport render_crossing(const RenderSettings& settings, const RailJointMesh& rails, const TriangleMesh& wheel,
                             const Trajectory& trajectory, const std::filesystem::path& out_dir,
                             const std::optional<PressureInputs>& contact_patch) {
  using clock = std::chrono::steady_clock;
  check_render_settings(settings);
  frame_window(settings, trajectory);  // reject a bad window before touching the disk
  prepare_output_folder(out_dir);
  const std::unique_ptr<CrossingView> view = CrossingView::make(settings, rails, wheel, trajectory);
  auto* top = dynamic_cast<TopView*>(view.get());
  if (contact_patch && top != nullptr) top->show_contact_patch(*contact_patch);

  RenderReport report;
  report.gl_version = view->gl_version();
  report.gl_renderer = view->gl_renderer();
  if (const auto* perspective = dynamic_cast<const PerspectiveView*>(view.get())) {
    report.overview_wheel_sides = perspective->overview_wheel_sides();
  }
  report.frame_pattern = out_dir / "frame_%05d.png";

  // The calling thread draws each frame (llvmpipe adds its threads), then
  // finishes it (FXAA, labels), feeds it to ffmpeg and writes its PNG;
  // ffmpeg, in its own process, sets the pace.
  std::optional<VideoPipe> video;
  if (settings.ffmpeg) video.emplace(out_dir, settings.width_px, settings.height_px, settings.video_fps);
  ReadBackFrame frame;  // both reused: their buffers are the size of every frame
  RgbImage image;
  double render_ms = 0.0, finish_ms = 0.0, encode_ms = 0.0;
  auto ms_between = [](clock::time_point a, clock::time_point b) {
    return std::chrono::duration<double, std::milli>(b - a).count();
  };
  const auto start = clock::now();
  for (long long k = 0; k < view->window().count; ++k) {
    const auto t0 = clock::now();
    view->draw_at(view->window().time_s(k), frame);
    const auto t1 = clock::now();
    finish_frame(frame, image);
    const auto t2 = clock::now();
    if (video) video->write(image);
    const auto t3 = clock::now();
    write_png(out_dir / frame_file_name(k), image);
    render_ms += ms_between(t0, t1);
    finish_ms += ms_between(t1, t2);
    encode_ms += ms_between(t3, clock::now());
    ++report.frames_written;
  }
  report.frames_wall_s = std::chrono::duration<double>(clock::now() - start).count();
  if (report.frames_written > 0) {
    const auto frames = static_cast<double>(report.frames_written);
    report.render_ms_per_frame = render_ms / frames;
    report.finish_ms_per_frame = finish_ms / frames;
    report.encode_ms_per_frame = encode_ms / frames;
  }

  if (settings.gltf) {
    const GltfReport gltf = write_crossing_gltf(out_dir / "crossing.glb", settings, rails, wheel, trajectory);
    report.gltf = gltf.path;
    report.gltf_keys = gltf.keys;
    report.gltf_slow_motion = gltf.slow_motion;
  }

  if (video) {
    const auto video_start = clock::now();
    static_cast<VideoFiles&>(report) = video->finish();
    report.video_wall_s = std::chrono::duration<double>(clock::now() - video_start).count();
  } else {
    report.video_note = "videos not requested (render.ffmpeg = false); PNG frames only";
  }
  return report;
}

}  // namespace railjoint
