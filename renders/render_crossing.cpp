#include "renders/render_crossing.h"

#include <chrono>
#include <cstdio>
#include <fstream>
#include <functional>
#include <optional>
#include <stdexcept>
#include <system_error>

#include "renders/crossing_gltf.h"
#include "renders/crossing_renderer.h"
#include "renders/frame_finisher.h"
#include "renders/perspective_view.h"
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
  // Find out now, not after the first frame was drawn, whether files can be written there.
  const std::filesystem::path probe = out_dir / ".railjoint_write_probe";
  {
    std::ofstream file(probe, std::ios::binary | std::ios::trunc);
    if (!file) throw std::runtime_error("render: the output folder '" + out_dir.string() + "' is not writable");
  }
  std::filesystem::remove(probe, ec);
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
  CrossingRenderer renderer(settings, rails, wheel, trajectory);
  if (contact_patch) renderer.show_contact_patch(*contact_patch);

  RenderReport report;
  report.gl_version = renderer.gl_version();
  report.gl_renderer = renderer.gl_renderer();
  if (const PerspectiveView* view = renderer.perspective()) report.overview_wheel_sides = view->overview_wheel_sides();
  report.frame_pattern = out_dir / "frame_%05d.png";

  // The calling thread draws each frame (llvmpipe adds its threads), then
  // finishes it (FXAA, labels), feeds it to ffmpeg and encodes it; ffmpeg,
  // in its own process, sets the pace. The pipe outlives the finisher that feeds it.
  std::optional<VideoPipe> video;
  if (settings.ffmpeg) video.emplace(out_dir, settings.width_px, settings.height_px, settings.video_fps);
  std::function<void(const RgbImage&)> to_video;
  if (video) to_video = [&video](const RgbImage& frame) { video->write(frame); };
  FrameFinisher finisher(to_video);
  double render_ms = 0.0;
  const auto start = clock::now();
  for (long long k = 0; k < renderer.window().count; ++k) {
    ReadBackFrame frame = finisher.spare_frame();
    const auto t0 = clock::now();
    renderer.draw_frame(k, frame);
    render_ms += std::chrono::duration<double, std::milli>(clock::now() - t0).count();
    finisher.push(out_dir / frame_file_name(k), std::move(frame));
  }
  report.frames_wall_s = std::chrono::duration<double>(clock::now() - start).count();
  report.frames_written = finisher.written();
  if (report.frames_written > 0) {
    report.render_ms_per_frame = render_ms / static_cast<double>(report.frames_written);
    report.finish_ms_per_frame = finisher.total_finish_ms() / static_cast<double>(report.frames_written);
    report.encode_ms_per_frame = finisher.total_encode_ms() / static_cast<double>(report.frames_written);
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
