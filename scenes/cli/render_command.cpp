// `railjoint render`: the Bullet crossing of one scene drawn off-screen
// (OSMesa) as PNG frames, and crossing.mp4 / crossing.gif when ffmpeg is on PATH.

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include "geometry/rail_joint_mesh.h"
#include "geometry/wheel_mesh.h"
#include "models/parameter_error.h"
#include "renders/offscreen_renderer.h"
#include "renders/render_crossing.h"
#include "renders/render_settings.h"
#include "renders/wheel_tessellation.h"
#include "scenes/cli/commands.h"
#include "scenes/input_error.h"
#include "scenes/scene_file.h"
#include "sim/simulate_crossing.h"

namespace railjoint::cli {

namespace {

struct RenderOptions {
  std::string scene_path;
  std::vector<std::string> overrides;
  std::string out_dir;
  bool impact_frame = false;
};

// Slow motion of the impact unless the scene sets a window: from this long
// before the simulated impact to this long after it (lift-off and landing
// follow within a few milliseconds at 50 m/s), clipped to the recorded run.
constexpr double kBeforeImpact_s = 1e-3;
constexpr double kAfterImpact_s = 2e-3;

// Creates the output folder and makes sure files can be written there, before
// the simulation runs: a typo in --out should not cost a run.
void prepare_output_folder(const std::filesystem::path& out_dir) {
  std::error_code ec;
  std::filesystem::create_directories(out_dir, ec);
  if (ec || !std::filesystem::is_directory(out_dir)) {
    throw InputError(out_dir.string(), "--out",
                     "cannot create this folder: " + (ec ? ec.message() : std::string("a file of that name exists")));
  }
  const std::filesystem::path probe = out_dir / ".railjoint_write_probe";
  {
    std::ofstream file(probe, std::ios::binary | std::ios::trunc);
    if (!file) throw InputError(out_dir.string(), "--out", "this folder is not writable");
  }
  std::filesystem::remove(probe, ec);
}

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

void run_render(const RenderOptions& options) {
  const Scene scene = load_scene(options.scene_path, options.overrides);
  // The user asked to render: a scene without [render] gets the defaults.
  RenderSettings settings = scene.render.value_or(RenderSettings{});
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
  const std::filesystem::path out_dir = options.out_dir;
  prepare_output_folder(out_dir);

  SimulationResult result;
  try {
    result = simulate_crossing(scene.joint, scene.wheel, scene.sim);
  } catch (const ParameterError& error) {
    throw InputError(scene.file, error.key(), error.what());
  }
  const std::string window_note = resolve_window(settings, result, options.impact_frame);

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
  const int segments = wheel_render_segments(settings, result.simulated_wheel.radius_m);
  const TriangleMesh wheel = build_wheel_mesh(result.simulated_wheel, segments, 0.0);

  RenderReport report;
  try {
    report = render_crossing(settings, rails, wheel, result.trajectory, out_dir);
  } catch (const ParameterError& error) {
    throw InputError(scene.file, error.key(), error.what());
  }

  std::printf("scene   %s (%s)\n", scene.name.c_str(), scene.file.c_str());
  if (result.impact_found) {
    std::printf("sim     impact at t = %.6f ms, wheel x = %.4f mm; lift-off %s\n", result.impact_time_s * 1e3,
                result.impact_x_m * 1e3, result.liftoff ? "yes" : "no");
    const double exact = result.prediction.impulse.exact_Ns;
    std::printf("jump    simulated %.4f N s, analytic %.4f N s (exact, v held; sim error %+.4f %%)", result.impulse_Ns,
                exact, 100.0 * (result.impulse_Ns - exact) / exact);
    if (result.thin_disc_prediction) {
      std::printf("; thin disc %.4f N s", result.thin_disc_prediction->impulse.exact_Ns);
    }
    std::printf("\n");
  } else {
    std::printf("sim     no impact found\n");
  }
  std::printf("GL      %s, %s\n", report.gl_version.c_str(), report.gl_renderer.c_str());
  std::printf("view    %dx%d %s, heights x%g about z = %g mm (wheel included), wheel drawn with %d sides, %.3f mm wide\n",
              settings.width_px, settings.height_px, to_string(settings.view), settings.exaggeration,
              settings.reference_z_m * 1e3, segments, result.simulated_wheel.width_m * 1e3);
  std::printf("window  %.6f .. %.6f ms at %g frames per simulated second (%s)\n", *settings.t_start_s * 1e3,
              *settings.t_end_s * 1e3, settings.fps, window_note.c_str());
  std::printf("frames  %lld written: %s\n", report.frames_written, report.frame_pattern.string().c_str());
  std::printf("time    mean %.2f ms render, %.2f ms encode per frame; %.2f s wall for the frames\n",
              report.render_ms_per_frame, report.encode_ms_per_frame, report.frames_wall_s);
  if (report.mp4 || report.gif) {
    std::printf("video   %s%s%s (%.2f s)\n", report.mp4 ? report.mp4->string().c_str() : "",
                report.mp4 && report.gif ? ", " : "", report.gif ? report.gif->string().c_str() : "",
                report.video_wall_s);
  } else {
    std::printf("video   none: %s\n", report.video_note.c_str());
  }
}

}  // namespace

void add_render_command(CLI::App& app) {
  auto options = std::make_shared<RenderOptions>();
  CLI::App* cmd = app.add_subcommand(
      "render",
      "Simulate the scene's crossing (as `simulate`) and draw it off-screen (OSMesa) as PNG frames\n"
      "DIR/frame_00000.png ..., plus DIR/crossing.mp4 and DIR/crossing.gif when ffmpeg is on PATH.\n"
      "Frames are taken at render.fps per SIMULATED second. Heights are exaggerated k-fold about\n"
      "render.reference_z for everything drawn, the wheel included (its circle becomes an ellipse), so\n"
      "the drawn wheel touches the drawn rails exactly where the real one touches the real rails.\n"
      "The side view is a section through the wheel's width, centred on its lowest point.");
  cmd->add_option("scene", options->scene_path,
                  "Scene file (TOML) as for `simulate`, optionally with [render] (absent: defaults), SI units:\n"
                  "  width, height [px] (1280 x 720), fps [1/simulated s] (20000), t_start, t_end [s]\n"
                  "  (absent: 1 ms before to 2 ms after the simulated impact), exaggeration (20),\n"
                  "  reference_z [m] (0), view = \"side\" | \"top\" | \"perspective\", follow (true),\n"
                  "  view_width [m] (side/perspective 0.12: the contact region; top: 3 rail widths high),\n"
                  "  ffmpeg (true), video_fps (25)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--set", options->overrides,
                  "Override a scene key: section.key=value (repeatable), e.g. render.view=top");
  cmd->add_option("--out", options->out_dir, "Folder for the frames and videos (created)")->required();
  cmd->add_flag("--impact-frame", options->impact_frame,
                "Write one frame only, at the simulated impact instant (a still for a report)");
  cmd->callback([options] { run_render(*options); });
}

}  // namespace railjoint::cli
