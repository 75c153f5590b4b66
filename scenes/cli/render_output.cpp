// Drawing a simulated crossing into a folder (render_output.h).

#include "scenes/cli/render_output.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "geometry/rail_joint_mesh.h"
#include "geometry/wheel_mesh.h"
#include "models/parameter_error.h"
#include "renders/offscreen_renderer.h"
#include "renders/render_crossing.h"
#include "renders/wheel_tessellation.h"
#include "scenes/cli/output_folder.h"
#include "scenes/input_error.h"

namespace railjoint::cli {

namespace {

// Slow motion of the impact unless the scene sets a window: from this long
// before the simulated impact to this long after it (lift-off and landing
// follow within a few milliseconds at 50 m/s), clipped to the recorded run.
constexpr double kBeforeImpact_s = 1e-3;
constexpr double kAfterImpact_s = 2e-3;

// The frame window: the scene's, else the slow-motion window around the impact.
// Returns a note saying which.
std::string resolve_window(RenderSettings& settings, const SimulationResult& result, bool impact_frame) {
  const auto& samples = result.trajectory.samples;
  if (samples.empty()) throw std::runtime_error("render: the simulation recorded no samples");
  const double first = samples.front().time_s, last = samples.back().time_s;
  if (impact_frame) {
    if (!result.impact_found) throw std::runtime_error("render: --impact-frame, but the simulation found no impact");
    // One frame: the window is shorter than one frame period.
    settings.t_start_s = result.impact_time_s;
    settings.t_end_s = std::min(last, result.impact_time_s + 0.5 / settings.fps);
    if (!(*settings.t_end_s > *settings.t_start_s)) settings.t_start_s = *settings.t_end_s - 0.5 / settings.fps;
    return "one frame at the simulated impact";
  }
  if (settings.t_start_s && settings.t_end_s) return "the scene's window";
  if (!result.impact_found) {
    if (!settings.t_start_s) settings.t_start_s = first;
    if (!settings.t_end_s) settings.t_end_s = last;
    return "no impact found: the whole run";
  }
  if (!settings.t_start_s) {
    settings.t_start_s = std::max(first, result.impact_time_s - kBeforeImpact_s);
    if (settings.t_end_s && !(*settings.t_start_s < *settings.t_end_s)) settings.t_start_s = first;
  }
  if (!settings.t_end_s) {
    settings.t_end_s = std::min(last, result.impact_time_s + kAfterImpact_s);
    if (!(*settings.t_end_s > *settings.t_start_s)) settings.t_end_s = last;
  }
  return "slow motion of the impact: 1 ms before to 2 ms after it, within the run";
}

}  // namespace

void prepare_rendering(const Scene& scene, const RenderSettings& settings, const std::filesystem::path& out_dir,
                       const char* out_option) {
  try {
    check_render_settings(settings);
    check_joint_geometry(scene.joint, scene.wheel);
  } catch (const ParameterError& error) {
    throw InputError(scene.file, error.key(), error.what());
  }
  if (!rendering_available()) {
    throw std::runtime_error("rendering unavailable: built without OSMesa (configure with RAILJOINT_WITH_OSMESA=ON "
                             "and the OSMesa development package installed)");
  }
  prepare_output_folder(out_dir, out_option);
}

RenderedCrossing render_simulated_crossing(const Scene& scene, const SimulationResult& result, RenderSettings settings,
                                           const std::filesystem::path& out_dir, bool impact_frame) {
  RenderedCrossing out;
  out.window_note = resolve_window(settings, result, impact_frame);

  // The rails and the wheel as simulated (a thin disc is simulated as a
  // cylinder of width 2 sim.disc_half_width: draw that width, no wider, so
  // the side view's section through the wheel is the one it rides on).
  RailJointMeshOptions rail_options;
  rail_options.flat_approach_m = scene.sim.flat_approach_m;
  RailJointMesh rails;
  try {
    rails = build_rail_joint_mesh(scene.joint, rail_options);
  } catch (const ParameterError& error) {
    throw InputError(scene.file, error.key(), error.what());
  }
  out.wheel_segments = wheel_render_segments(settings, result.simulated_wheel.radius_m);
  out.wheel_width_m = result.simulated_wheel.width_m;
  const TriangleMesh wheel = build_wheel_mesh(result.simulated_wheel, out.wheel_segments, 0.0);

  try {
    out.report = render_crossing(settings, rails, wheel, result.trajectory, out_dir);
  } catch (const ParameterError& error) {
    throw InputError(scene.file, error.key(), error.what());
  }
  out.settings = settings;
  return out;
}

void print_render_report(const RenderedCrossing& rendered, std::FILE* log) {
  const RenderReport& report = rendered.report;
  const RenderSettings& settings = rendered.settings;

  std::fprintf(log, "GL      %s, %s\n", report.gl_version.c_str(), report.gl_renderer.c_str());
  std::fprintf(log, "view    %dx%d %s, heights x%g about z = %g mm (wheel included), wheel drawn with %d sides, %.3f mm wide\n",
              settings.width_px, settings.height_px, to_string(settings.view), settings.exaggeration,
              settings.reference_z_m * 1e3, rendered.wheel_segments, rendered.wheel_width_m * 1e3);
  std::fprintf(log, "window  %.6f .. %.6f ms at %g frames per simulated second (%s)\n", *settings.t_start_s * 1e3,
              *settings.t_end_s * 1e3, settings.fps, rendered.window_note.c_str());
  std::fprintf(log, "frames  %lld written: %s\n", report.frames_written, report.frame_pattern.string().c_str());
  std::fprintf(log, "time    mean %.2f ms render, %.2f ms encode per frame; %.2f s wall for the frames\n",
              report.render_ms_per_frame, report.encode_ms_per_frame, report.frames_wall_s);
  if (report.mp4 || report.gif) {
    std::fprintf(log, "video   %s%s%s (%.2f s)\n", report.mp4 ? report.mp4->string().c_str() : "",
                report.mp4 && report.gif ? ", " : "", report.gif ? report.gif->string().c_str() : "",
                report.video_wall_s);
  } else {
    std::fprintf(log, "video   none: %s\n", report.video_note.c_str());
  }
}

}  // namespace railjoint::cli
