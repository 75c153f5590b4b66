#pragma once
// Drawing a simulated crossing into a folder: shared by `railjoint render`
// and by `railjoint simulate` when the scene has a [render] section.

#include <cstdio>
#include <filesystem>
#include <string>

#include "renders/render_crossing.h"
#include "renders/render_settings.h"
#include "scenes/scene_file.h"
#include "sim/simulate_crossing.h"

namespace railjoint::cli {

/// Checks the render settings and that rendering was built, and creates
/// out_dir and makes sure it is writable: all before the simulation runs, so
/// a typo costs no run. Throws InputError naming the file and key (for the
/// folder: out_option, the command-line option that named it).
void prepare_rendering(const Scene& scene, const RenderSettings& settings, const std::filesystem::path& out_dir,
                       const char* out_option);

/// What was drawn, for the report.
struct RenderedCrossing {
  RenderReport report;
  RenderSettings settings;  ///< with the time window resolved
  std::string window_note;  ///< which window was used and why
  int wheel_segments = 0;
  double wheel_width_m = 0.0;  ///< as simulated (a thin disc: 2 sim.disc_half_width)
};

/// Renders the recorded crossing into out_dir (frames, and videos when
/// ffmpeg is there). Without a time window in the settings: slow motion of
/// the impact; with impact_frame: one frame at the impact instant.
RenderedCrossing render_simulated_crossing(const Scene& scene, const SimulationResult& result, RenderSettings settings,
                                           const std::filesystem::path& out_dir, bool impact_frame);

/// GL version, view, window, frames, frame time and videos, one line each.
void print_render_report(const RenderedCrossing& rendered, std::FILE* log);

}  // namespace railjoint::cli
