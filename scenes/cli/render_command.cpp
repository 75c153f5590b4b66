// `railjoint render`: the Bullet crossing of one scene drawn off-screen
// (OSMesa) as PNG frames, crossing.glb, and crossing.mp4 / crossing.gif
// when ffmpeg is on PATH.

#include <cstdio>
#include <memory>
#include <string>

#include "renders/render_settings.h"
#include "scenes/cli/commands.h"
#include "scenes/cli/output_folder.h"
#include "scenes/cli/scene_command.h"
#include "scenes/cli/crossing_drawing.h"
#include "scenes/cli/render_report.h"
#include "scenes/report/simulation_text.h"
#include "sim/simulate_crossing.h"

namespace railjoint::cli {

namespace {

const SceneCommandHelp kHelp = {
    "render",
    "Simulate the scene's crossing (as `simulate`) and draw it off-screen as PNG frames\n"
    "DIR/frame_00000.png ..., the animated glTF DIR/crossing.glb, and DIR/crossing.mp4 and\n"
    "DIR/crossing.gif when ffmpeg is on PATH. GL: OSMesa (Mesa's llvmpipe, no GPU needed).\n"
    "Frames are taken at render.fps per SIMULATED second. Heights are exaggerated k-fold about\n"
    "render.reference_z for everything drawn, the wheel included (its circle becomes an ellipse), so\n"
    "the drawn wheel touches the drawn rails exactly where the real one touches the real rails.\n"
    "The side view is a section through the wheel's width, centred on its lowest point; the\n"
    "perspective view shows the whole wheel to scale with an exaggerated inset of the contact.",
    "Scene file (TOML) as for `simulate`, optionally with [render] (absent: defaults), SI units:\n"
    "  width, height [px] (1280 x 720), fps [1/simulated s] (20000), t_start, t_end [s, t = 0 when\n"
    "  the centre passes the predicted impact, as in simulate's outputs; negative before it]\n"
    "  (absent: 1 ms before to 2 ms after the simulated impact), exaggeration (20),\n"
    "  reference_z [m] (0), view = \"side\" | \"top\" | \"perspective\", follow (true),\n"
    "  view_width [m] (side/perspective 0.12: the contact region; top: 3 rail widths high),\n"
    "  antialias = \"fxaa\" | \"msaa\" | \"none\", gltf (true: crossing.glb), ffmpeg (true), video_fps (25)",
    "render.view=top"};

struct RenderOptions {
  std::string out_dir;
  bool impact_frame = false;
};

void run_render(const Scene& scene, const RenderOptions& options) {
  // The user asked to render: a scene without [render] gets the defaults.
  const RenderSettings settings = scene.render.value_or(RenderSettings{});
  if (options.impact_frame) check_impact_frame_keys(scene);
  check_rendering(settings);
  const ContactPatchForRender contact_patch = contact_patch_for_render(scene, settings);  // may refuse a key: before the run
  prepare_output_folder(options.out_dir, "--out");
  const SimulationResult result = simulate_crossing(scene.crossing);
  const RenderedCrossing rendered =
      render_simulated_crossing(result, settings, options.out_dir, "--out", options.impact_frame, contact_patch);
  print_simulation_brief(scene, result);
  print_render_report(rendered, stdout);
}

void add_render_options(CLI::App& cmd, RenderOptions& options) {
  cmd.add_option("--out", options.out_dir, "Folder for the frames and videos (created)")->required();
  cmd.add_flag("--impact-frame", options.impact_frame,
               "Write one frame only, at the simulated impact instant (a still for a report; no MP4 or GIF)");
}

}  // namespace

void add_render_command(CLI::App& app) {
  add_scene_command(app, kHelp, SceneCheck::simulation, add_render_options, run_render);
}

}  // namespace railjoint::cli
