// `railjoint render`: the Bullet crossing of one scene drawn off-screen
// (OSMesa) as PNG frames, and crossing.mp4 / crossing.gif when ffmpeg is on PATH.

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "models/parameter_error.h"
#include "renders/render_settings.h"
#include "scenes/cli/commands.h"
#include "scenes/cli/render_output.h"
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

void run_render(const RenderOptions& options) {
  const Scene scene = load_scene(options.scene_path, options.overrides);
  // The user asked to render: a scene without [render] gets the defaults.
  const RenderSettings settings = scene.render.value_or(RenderSettings{});
  prepare_rendering(scene, settings, options.out_dir, "--out");
  SimulationResult result;
  try {
    result = simulate_crossing(scene.joint, scene.wheel, scene.sim);
  } catch (const ParameterError& error) {
    throw InputError(scene.file, error.key(), error.what());
  }
  const RenderedCrossing rendered =
      render_simulated_crossing(scene, result, settings, options.out_dir, options.impact_frame);
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
  print_render_report(rendered, stdout);
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
      ->required();
  cmd->add_option("--set", options->overrides,
                  "Override a scene key: section.key=value (repeatable), e.g. render.view=top");
  cmd->add_option("--out", options->out_dir, "Folder for the frames and videos (created)")->required();
  cmd->add_flag("--impact-frame", options->impact_frame,
                "Write one frame only, at the simulated impact instant (a still for a report)");
  cmd->callback([options] { run_render(*options); });
}

}  // namespace railjoint::cli
