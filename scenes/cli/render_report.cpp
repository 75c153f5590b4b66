// What a drawn crossing wrote, one line per item (render_report.h).

#include "scenes/cli/render_report.h"

#include <string>

namespace railjoint {

void print_render_report(const RenderedCrossing& rendered, std::FILE* log) {
  const RenderReport& report = rendered.report;
  const RenderSettings& settings = rendered.settings;

  std::fprintf(log, "GL      OSMesa: %s, %s\n", report.gl_version.c_str(), report.gl_renderer.c_str());
  const std::string overview_sides =
      report.overview_wheel_sides > 0 ? " (" + std::to_string(report.overview_wheel_sides) + " in the overview)" : "";
  std::fprintf(log, "view    %dx%d %s (anti-aliasing %s), heights x%g about z = %g mm (wheel included), wheel drawn with %d sides%s, %.3f mm wide\n",
              settings.width_px, settings.height_px, to_string(settings.view), to_string(settings.antialiasing), settings.exaggeration,
              settings.reference_z_m * 1e3, rendered.wheel_segments, overview_sides.c_str(), rendered.wheel_width_m * 1e3);
  std::fprintf(log, "window  %.6f .. %.6f ms at %g frames per simulated second (%s)\n", *settings.t_start_s * 1e3,
              *settings.t_end_s * 1e3, settings.fps, rendered.window_note.c_str());
  std::fprintf(log, "frames  %lld written: %s\n", report.frames_written, report.frame_pattern.string().c_str());
  std::fprintf(log,
               "time    mean %.2f ms draw (GL), %.2f ms finish (FXAA, labels), %.2f ms encode (PNG) per frame; %.2f s wall "
               "for the frames (%.2f ms a frame, %.0f frames per second)\n",
               report.render_ms_per_frame, report.finish_ms_per_frame, report.encode_ms_per_frame, report.frames_wall_s,
               report.frames_written > 0 ? 1e3 * report.frames_wall_s / static_cast<double>(report.frames_written) : 0.0,
               report.frames_wall_s > 0.0 ? static_cast<double>(report.frames_written) / report.frames_wall_s : 0.0);
  if (!rendered.contact_patch_note.empty()) std::fprintf(log, "patch   %s\n", rendered.contact_patch_note.c_str());
  if (report.gltf) {
    std::fprintf(log, "glTF    %s: wheel keyed at %lld recorded states, played %gx slower than simulated\n",
                 report.gltf->string().c_str(), report.gltf_keys, report.gltf_slow_motion);
  }
  if (report.mp4 || report.gif) {
    // The playing time first: a bare "(0.58 s)" read as the video's length.
    std::fprintf(log, "video   %s%s%s: %lld frames at %g a second, %.2f s long; ffmpeg finished %.2f s after the last frame\n",
                 report.mp4 ? report.mp4->string().c_str() : "", report.mp4 && report.gif ? ", " : "",
                 report.gif ? report.gif->string().c_str() : "", report.frames_written, settings.video_fps,
                 static_cast<double>(report.frames_written) / settings.video_fps, report.video_wall_s);
  } else {
    std::fprintf(log, "video   none: %s\n", report.video_note.c_str());
  }
}

}  // namespace railjoint
