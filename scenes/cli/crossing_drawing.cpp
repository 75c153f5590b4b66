// Drawing a simulated crossing into a folder (crossing_drawing.h).

#include "scenes/cli/crossing_drawing.h"

#include <algorithm>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <string>

#include "geometry/rail_joint_mesh.h"
#include "geometry/wheel_mesh.h"
#include "models/local_model_settings.h"
#include "renders/offscreen_renderer.h"
#include "renders/render_crossing.h"
#include "renders/wheel_tessellation.h"
#include "sim/time_origin.h"
#include "support/input_error.h"
#include "support/render_folder.h"

namespace railjoint {

namespace {

// Slow motion of the impact unless the scene sets a window: from this long
// before the simulated impact to this long after it (lift-off and landing
// follow within a few milliseconds at 50 m/s), clipped to the recorded run.
constexpr double kBeforeImpact_s = 1e-3;
constexpr double kAfterImpact_s = 2e-3;

// The frame window on `trajectory`'s clock (the outputs'): the scene's,
// else the slow-motion window around the impact at `impact_s` (none: the
// run found none). Returns a note saying which.
std::string resolve_window(RenderSettings& settings, const Trajectory& trajectory, std::optional<double> impact_s,
                           bool impact_frame) {
  const auto& samples = trajectory.samples;
  if (samples.empty()) throw std::runtime_error("render: the simulation recorded no samples");
  const double first = samples.front().time_s, last = samples.back().time_s;
  if (impact_frame) {
    if (!impact_s) throw std::runtime_error("render: --impact-frame, but the simulation found no impact");
    // One frame: the window is shorter than one frame period, and no video
    // (a one-frame MP4 and GIF show nothing the PNG does not).
    settings.ffmpeg = false;
    settings.t_start_s = *impact_s;
    settings.t_end_s = std::min(last, *impact_s + 0.5 / settings.fps);
    if (!(*settings.t_end_s > *settings.t_start_s)) settings.t_start_s = *settings.t_end_s - 0.5 / settings.fps;
    return "one frame at the simulated impact";
  }
  if (settings.t_start_s && settings.t_end_s) return "the scene's window";
  if (!impact_s) {
    if (!settings.t_start_s) settings.t_start_s = first;
    if (!settings.t_end_s) settings.t_end_s = last;
    return "no impact found: the whole run";
  }
  const bool start_given = settings.t_start_s.has_value(), end_given = settings.t_end_s.has_value();
  if (!start_given) {
    settings.t_start_s = std::max(first, *impact_s - kBeforeImpact_s);
    if (settings.t_end_s && !(*settings.t_start_s < *settings.t_end_s)) settings.t_start_s = first;
  }
  if (!end_given) {
    settings.t_end_s = std::min(last, *impact_s + kAfterImpact_s);
    if (!(*settings.t_end_s > *settings.t_start_s)) settings.t_end_s = last;
  }
  // Says what was chosen: one end may be the scene's (render.t_end changed).
  if (start_given) return "the scene's render.t_start, then up to 2 ms after the impact, within the run";
  if (end_given) return "from 1 ms before the impact (within the run) to the scene's render.t_end";
  return "slow motion of the impact: 1 ms before to 2 ms after it, within the run";
}

}  // namespace

void check_impact_frame_keys(const Scene& scene) {
  for (const char* key : {"render.t_start", "render.t_end", "render.fps"}) {
    if (scene.given(key)) {
      throw InputError(scene.file, key,
                       "changes nothing with --impact-frame (one frame at the simulated impact); "
                       "drop the key or the flag");
    }
  }
}

void check_rendering(const RenderSettings& settings) {
  // The joint and wheel were checked with the crossing (Scene::crossing).
  check_render_settings(settings);
  if (!rendering_available()) {
    throw std::runtime_error("rendering unavailable: built without OSMesa (install libosmesa6-dev and "
                             "configure with -DRAILJOINT_WITH_OSMESA=ON)");
  }
}

ContactPatchForRender contact_patch_for_render(const Scene& scene, const RenderSettings& settings) {
  const bool patch_given = std::any_of(scene.given_keys.begin(), scene.given_keys.end(),
                                       [](const std::string& key) { return key.rfind("contact_patch.", 0) == 0; });
  if (settings.view != RenderView::top) {
    if (!patch_given) return {};
    return {std::nullopt, std::string("not drawn: the local model's contact patch ([contact_patch]) is drawn in the top "
                                      "view only (render.view = \"top\"), this is the ") + to_string(settings.view) + " view"};
  }
  if (!(scene.joint.gap_m > 0.0)) {
    return {std::nullopt, "not drawn: the joint has no end-post gap (joint.gap = 0), so the local model has none to show"};
  }
  if (scene.joint.kind != JointKind::inclined) {
    return {std::nullopt, "not drawn: the local model describes an inclined cut, and this joint is a step"};
  }
  try {
    const PressureInputs inputs = local_model_inputs(scene.contact_patch, scene.joint, scene.wheel);
    char text[200];
    std::snprintf(text, sizeof text, "the local model's contact patch: %s %.1f x %.1f mm (%s), over the %.1f mm gap",
                  to_string(inputs.patch.shape), inputs.patch.length_m * 1e3, inputs.patch.width_m * 1e3,
                  scene.contact_patch.size == PatchSize::hertz ? "Hertz" : "given", scene.joint.gap_m * 1e3);
    return {inputs, text};
  } catch (const InputError& error) {
    // A patch the user set ([contact_patch] keys given) that the local model
    // refuses on this joint is bad input (exit 2, as `pressure` says, whichever
    // key the error names); the default patch that does not fit this joint is
    // only not drawn.
    if (patch_given) throw;
    return {std::nullopt, "not drawn: key '" + error.key() + "': " + one_line(error.message())};
  }
}

RenderedCrossing render_simulated_crossing(const SimulationResult& result, RenderSettings settings,
                                           const std::filesystem::path& out_dir, const char* out_option, bool impact_frame,
                                           const ContactPatchForRender& contact_patch) {
  RenderedCrossing out;
  // Drawn on the outputs' clock: t = 0 when the centre passes the predicted
  // impact (sim/time_origin.h), as the JSON and CSV of the same run.
  const double origin_s = simulation_time_origin_s(result);
  const Trajectory trajectory = on_output_clock(result.trajectory, origin_s);
  std::optional<double> impact_s;
  if (result.impact_found()) impact_s = result.impact->time_s() - origin_s;
  out.window_note = resolve_window(settings, trajectory, impact_s, impact_frame);

  // The rails the simulation ran on (its model's, not built again) and the
  // wheel as simulated (a thin disc is simulated as a cylinder of width
  // 2 sim.disc_half_width: draw that width, no wider, so the side view's
  // section through the wheel is the one it rides on).
  const RailJointMesh& rails = result.model->rails;
  out.wheel_segments = wheel_render_segments(settings, result.model->simulated_wheel.radius_m);
  // A disc simulated as a disc (analytic rail tops) is drawn as its
  // broadphase cylinder, 2 sim.disc_half_width wide.
  const double min_width_m = 2.0 * result.model->settings.disc_half_width_m;
  out.wheel_width_m = std::max(result.model->simulated_wheel.width_m, min_width_m);
  const TriangleMesh wheel = build_wheel_mesh(result.model->simulated_wheel, out.wheel_segments, min_width_m);

  // Drawn into a staging folder and published whole (render_folder.h).
  StagingFolder staging(out_dir, out_option);
  try {
    out.report = render_crossing(settings, rails, wheel, trajectory, staging.path(), contact_patch.inputs);
  } catch (const std::runtime_error& error) {
    throw std::runtime_error(staging.published_text(error.what()));  // name the frame where the user will look
  }
  if (impact_frame) {
    out.report.video_note = "one frame (--impact-frame): an MP4 or GIF of it would show nothing its PNG does not";
  }
  out.report.video_note = publish_render(staging, out.report.video_note);
  out.report.frame_pattern = out_dir / out.report.frame_pattern.filename();
  if (out.report.mp4) out.report.mp4 = out_dir / out.report.mp4->filename();
  if (out.report.gif) out.report.gif = out_dir / out.report.gif->filename();
  if (out.report.gltf) out.report.gltf = out_dir / out.report.gltf->filename();
  out.settings = settings;
  out.contact_patch_note = contact_patch.note;
  return out;
}

}  // namespace railjoint
