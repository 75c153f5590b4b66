#pragma once
// Drawing a simulated crossing into a folder: the part of a scene run that
// only a scene with a [render] section (or `railjoint render`) builds. Shared
// by `railjoint render` and `railjoint simulate`; scenes/cli/render_report.h
// prints what was drawn.

#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>

#include "models/pressure_traversal.h"
#include "renders/render_crossing.h"
#include "renders/render_settings.h"
#include "scenes/scene_file.h"
#include "sim/simulate_crossing.h"

namespace railjoint {

/// Checks the render settings and that rendering was built, before the
/// simulation runs, so a typo costs no run: InputError naming the key, or a
/// runtime_error for a build without OSMesa.
/// The joint and wheel were checked with the scene's crossing (Scene::crossing).
void check_rendering(const RenderSettings& settings);

/// --impact-frame draws one frame at the simulated impact: a scene key of
/// the frame window (render.t_start, t_end, fps) would change nothing, and
/// is refused (InputError naming it) like any key that does nothing.
void check_impact_frame_keys(const Scene& scene);

/// The local model's contact patch for the top view (renders/joint_contact_patch.h):
/// the scene's [contact_patch] on its joint, when the view is the top view
/// and the joint an inclined cut with an end-post gap the model accepts.
/// `note` says what is drawn, or why not (in the other views: empty, or that
/// the patch is drawn in the top view only when [contact_patch] keys were
/// given). Throws the local model's InputError when it refuses a
/// [contact_patch] key the scene or a --set gave.
struct ContactPatchForRender {
  std::optional<PressureInputs> inputs;
  std::string note;
};
ContactPatchForRender contact_patch_for_render(const Scene& scene, const RenderSettings& settings);

/// What was drawn, for the report.
struct RenderedCrossing {
  RenderReport report;
  RenderSettings settings;  ///< with the time window resolved
  std::string window_note;  ///< which window was used and why
  int wheel_segments = 0;
  double wheel_width_m = 0.0;  ///< as simulated (a thin disc: 2 sim.disc_half_width)
  std::string contact_patch_note;  ///< top view: the local model's patch drawn, or why not
};

/// Renders the recorded crossing into out_dir (frames, and videos when
/// ffmpeg is there), published whole when complete, replacing an older
/// render's files there (render_folder.h). Without a time window in the
/// settings: slow motion of the impact; with impact_frame: one frame at the
/// impact instant. Errors about out_dir's files name `out_option` (the
/// command's option for it: "--out", "--render-out").
RenderedCrossing render_simulated_crossing(const SimulationResult& result, RenderSettings settings,
                                           const std::filesystem::path& out_dir, const char* out_option, bool impact_frame,
                                           const ContactPatchForRender& contact_patch = {});

}  // namespace railjoint
