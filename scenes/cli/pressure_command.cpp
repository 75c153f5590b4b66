// `railjoint pressure`: the local model of thesis chapters 5-6, the contact
// pressure of a patch crossing the end-post gap. Never builds a Bullet world.

#include <algorithm>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <optional>
#include <string>
#include <vector>

#include "renders/patch_crossing_frames.h"
#include "renders/solved_contact_frames.h"
#include "scenes/cli/commands.h"
#include "scenes/cli/figure_script.h"
#include "scenes/cli/output_folder.h"
#include "scenes/cli/scene_command.h"
#include "scenes/local_model_run.h"
#include "scenes/report/json_values.h"
#include "scenes/report/pressure_figure_data.h"
#include "scenes/report/pressure_report.h"
#include "scenes/report/solved_contact_report.h"
#include "support/input_error.h"
#include "support/render_folder.h"

namespace railjoint::cli {

namespace {

const SceneCommandHelp kHelp = {
    "pressure",
    "Local model (thesis ch. 5-6): uniform contact pressure N / A of a contact patch crossing the\n"
    "end-post gap, its exact rate of change dP/dt, the maxima and the five points of fig. 6.3;\n"
    "beyond the thesis, the Hertzian pressure over the bearing part and a Hertz-sized patch; shape =\n"
    "\"solved\": the contact solved on the surfaces (boundary elements, elastic or capped).",
    "Scene file (TOML). theta_deg and gap [m] from [joint], speed v [m/s] and radius [m] from [wheel];\n"
    "  [contact_patch] shape = \"ellipse\"|\"polygon\"|\"rectangle\", size = \"given\"|\"hertz\",\n"
    "      length a [m] = 0.016, width b [m] = 0.012 (size given), vertices = 100 (polygon),\n"
    "      normal_force N [N] = 112.5e3, steps = 1000,\n"
    "      (shape solved) normal_force = \"forces\": N(x) from the scene's force run ([sim] mode\n"
    "      \"inertial\", [contact] law \"hertz\", [track]), so that the rail end sees P1,\n"
    "      crown_radius [m] = 0.3 (size hertz);\n"
    "  [contact] youngs_modulus [Pa] = 210e9, poisson_ratio = 0.3 (the steels, for the whole program)",
    "joint.theta_deg=45",
    // [sim], [track] and [vehicle] for normal_force = "forces"; not [render]:
    // --frames draws the patch.
    {"joint", "wheel", "contact", "contact_patch", "sim", "track", "vehicle"}};

struct PressureOptions {
  bool json = false;
  std::string csv_path;
  std::string out_dir;
  std::string frames_dir;
  std::string map_path;
  int frame_count = 60;
  int frame_width = 960;
  int frame_height = 540;
};

// shape = "solved": the boundary-element crossing, its CSV, pressure map
// and frames (one a step, or --frame-count of them evenly among the steps).
void run_solved_pressure(const Scene& scene, const PressureOptions& o) {
  if (!o.out_dir.empty()) {
    throw InputError("--out", "not available with contact_patch.shape = \"solved\" (use --csv, --map and --frames)");
  }
  if (!o.csv_path.empty() && !o.map_path.empty()) refuse_same_output(o.csv_path, "--csv", o.map_path, "--map");
  if (!o.csv_path.empty() && !o.frames_dir.empty()) refuse_same_output(o.csv_path, "--csv", o.frames_dir, "--frames");
  if (!o.map_path.empty() && !o.frames_dir.empty()) refuse_same_output(o.map_path, "--map", o.frames_dir, "--frames");
  std::optional<StagingFolder> staging;
  if (!o.frames_dir.empty()) {
    prepare_output_folder(o.frames_dir, "--frames");
    staging.emplace(o.frames_dir, "--frames");
  }
  const SolvedContactRun run = run_solved_contact(scene, staging.has_value());
  const std::vector<RailEndField>& fields = run.fields;
  const RailEndCrossing& crossing = run.crossing;
  if (staging) {
    const std::size_t n = fields.size();
    const std::size_t count = std::min(n, static_cast<std::size_t>(o.frame_count));
    std::vector<RailEndField> frames;
    for (std::size_t k = 0; k < count; ++k) {
      frames.push_back(fields[count == 1 ? 0 : (k * (n - 1) + (count - 1) / 2) / (count - 1)]);
    }
    SolvedContactFrames written;
    try {
      written = write_solved_contact_frames(scene.joint, frames, staging->path(), o.frame_width, o.frame_height);
    } catch (const std::runtime_error& error) {
      throw std::runtime_error(staging->published_text(error.what()));
    }
    written.video_note = publish_render(*staging, written.video_note);
    std::cerr << written.frames_written << " frames in " << o.frames_dir << " (the pressure on one scale, 0 black "
              << "to the peak white; the cut faces blue; the bar: the step's load against the largest); "
              << written.video_note << '\n';
  }
  if (!o.csv_path.empty()) {
    const bool elastic = !scene.contact_patch.solved_contact.yield_pressure_Pa;
    write_output_file(o.csv_path, "--csv", [&](std::ostream& out) { write_solved_contact_csv(crossing, elastic, out); });
  }
  if (!o.map_path.empty()) {
    write_output_file(o.map_path, "--map", [&](std::ostream& out) { write_solved_pressure_map_csv(crossing, out); });
  }
  if (o.json) {
    std::cout << report_text(solved_contact_to_json(scene, run)) << '\n';
  } else {
    print_solved_contact_summary(scene, run, std::cout);
  }
  const std::vector<std::string> doubts = solved_contact_doubts(run);
  if (!doubts.empty()) {
    std::cout.flush();
    std::string reason;
    for (const std::string& d : doubts) reason += (reason.empty() ? "" : "; ") + d;
    throw std::runtime_error(scene.file + ": " + reason);
  }
}

void run_pressure(const Scene& scene, const PressureOptions& o) {
  if (scene.contact_patch.solved) {
    run_solved_pressure(scene, o);
    return;
  }
  if (!o.map_path.empty()) throw InputError("--map", "only with contact_patch.shape = \"solved\"");
  if (!o.csv_path.empty() && !o.out_dir.empty()) refuse_same_output(o.csv_path, "--csv", o.out_dir, "--out");
  if (!o.csv_path.empty() && !o.frames_dir.empty()) refuse_same_output(o.csv_path, "--csv", o.frames_dir, "--frames");
  if (!o.out_dir.empty()) prepare_output_folder(o.out_dir, "--out");
  if (!o.frames_dir.empty()) prepare_output_folder(o.frames_dir, "--frames");
  const LocalModelRun result = run_local_model(scene);
  if (!o.csv_path.empty()) {
    write_output_file(o.csv_path, "--csv", [&](std::ostream& out) { write_pressure_csv(result, out); });
  }
  if (!o.out_dir.empty()) {
    write_pressure_figure_data(scene, result, o.out_dir);
    std::cerr << run_figure_script("pressure_figures.py", {o.out_dir}).message << " in " << o.out_dir << '\n';
  }
  if (!o.frames_dir.empty()) {
    StagingFolder staging(o.frames_dir, "--frames");  // published whole (support/render_folder.h)
    PatchCrossingFrames frames;
    try {
      frames = render_patch_crossing(result.inputs, staging.path(), o.frame_count, o.frame_width, o.frame_height);
    } catch (const std::runtime_error& error) {
      throw std::runtime_error(staging.published_text(error.what()));
    }
    frames.video_note = publish_render(staging, frames.video_note);
    std::cerr << frames.frames_written << " frames in " << o.frames_dir << " (" << frames.draw_ms_per_frame
              << " ms a frame to draw); " << frames.video_note << '\n';
  }
  if (o.json) {
    std::cout << report_text(pressure_to_json(scene, result)) << '\n';
  } else {
    print_pressure_summary(scene, result, std::cout);
  }
}

void add_pressure_options(CLI::App& cmd, PressureOptions& o) {
  cmd.add_flag("--json", o.json, "Print one JSON object (SI units) instead of the summary");
  cmd.add_option("--csv", o.csv_path, "Write the traversal (areas, pressure, rate; Hertzian peak and rail-end forces) as CSV");
  cmd.add_option("--out", o.out_dir, "Write the thesis's figures 5.2-5.4, 6.1-6.3, 6.5, 6.6 and a theta sweep (PNG + CSV) here");
  cmd.add_option("--map", o.map_path, "shape = \"solved\": write the pressure map at the peak (x, y, gap, pressure) as CSV");
  cmd.add_option("--frames", o.frames_dir, "Render a top view of the patch crossing the gap as PNG frames (+ MP4/GIF with ffmpeg) here; shape = \"solved\": the pressure field");
  cmd.add_option("--frame-count", o.frame_count, "Frames over the crossing (with --frames)")->check(CLI::Range(2, 100000));
  cmd.add_option("--frame-width", o.frame_width, "Frame width [px] (with --frames)")->check(CLI::Range(160, 7680));
  cmd.add_option("--frame-height", o.frame_height, "Frame height [px] (with --frames)")->check(CLI::Range(120, 4320));
}

}  // namespace

void add_pressure_command(CLI::App& app) {
  add_scene_command(app, kHelp, SceneCheck::keys_only, add_pressure_options, run_pressure);
}

}  // namespace railjoint::cli
