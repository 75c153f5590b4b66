// `railjoint study convergence`: error against run time over a ladder of
// step sizes and solver iterations (scenes/studies/convergence_study.h).

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "scenes/cli/command.h"
#include "scenes/cli/commands.h"
#include "scenes/cli/figure_script.h"
#include "scenes/cli/jobs_option.h"
#include "scenes/cli/output_folder.h"
#include "scenes/report/report_text.h"
#include "scenes/scene_file.h"
#include "scenes/studies/convergence_study.h"
#include "sim/setting_checks.h"
#include "sim/simulate_crossing.h"
#include "support/input_error.h"

namespace railjoint::cli {

namespace {

namespace fs = std::filesystem;

struct ConvergenceOptions {
  std::vector<std::string> scene_paths;
  std::vector<std::string> overrides;
  std::string out_dir = "out/studies";
  int repeats = 5;
  bool figures = true;
  int jobs = available_cores();
};

constexpr const char* kDescription =
    "Error against run time: simulates each scene over a ladder of numerical settings -- fixed\n"
    "steps 1e-3 .. 1e-6 s (no refinement), a 1e-4 s step refined to 1e-5 .. 1e-7 s near contact,\n"
    "1 .. 100 solver iterations, the gap contacts are solved from 1e-8 .. 1e-12 m, Bullet's own\n"
    "narrow phase -- and reports |error| of the vertical momentum jump against the exact analytic\n"
    "jump of the governing slice as simulated, the median wall time of --repeats runs, the\n"
    "Pareto-best settings and whether the scene's settings are among them; with several scenes also\n"
    "each setting's worst error over all of them against its total time (the default's question).\n"
    "Writes convergence_<scene>.csv and .png (log-log error against wall time) into --out.";

// Every scene is loaded and checked before the first run: a bad file or key
// fails in a second, not after minutes of the other scenes' ladders.
std::vector<Scene> load_simulable_scenes(const ConvergenceOptions& options) {
  std::vector<Scene> scenes;
  for (const std::string& path : options.scene_paths) {
    Scene scene = load_scene(path, options.overrides);
    try {
      check_simulation_inputs(scene.joint, scene.wheel, scene.sim);
    } catch (const InputError& error) {
      throw error.in_file(scene.file);
    }
    scenes.push_back(std::move(scene));
  }
  return scenes;
}

void run_convergence(const ConvergenceOptions& options) {
  const std::vector<Scene> scenes = load_simulable_scenes(options);
  prepare_output_folder(options.out_dir, "--out");
  std::vector<std::string> csv_paths;
  std::vector<std::string> without_impact;
  std::vector<ConvergenceStudy> studies;
  for (const Scene& scene : scenes) {
    const std::vector<ConvergenceSetting> ladder = convergence_ladder(scene.sim);
    const ConvergenceStudy study =
        run_convergence_study(scene, ladder, options.repeats, {options.jobs, "study convergence " + scene.name});
    const std::string csv = (fs::path(options.out_dir) / ("convergence_" + scene.name + ".csv")).string();
    write_output_file(csv, "--out", [&](std::ostream& out) { convergence_table(study).write_csv(out); });
    csv_paths.push_back(csv);
    std::cout << convergence_report(study) << "table: " << csv << "\n\n";
    const bool any_impact = std::any_of(study.points.begin(), study.points.end(),
                                        [](const ConvergencePoint& p) { return p.impact_found; });
    if (!any_impact) without_impact.push_back(scene.file);
    studies.push_back(study);
  }
  if (studies.size() > 1) std::cout << convergence_overall_report(convergence_over_scenes(studies), studies.size()) << '\n';
  // No point with an error has no curve to draw: an error, not an empty plot.
  if (!without_impact.empty()) {
    throw std::runtime_error("study convergence: no setting of the ladder found an impact for " +
                             join(without_impact, ", ") + " (see the failure column of the table)");
  }
  if (!options.figures) return;
  // One figure per scene, and one with a panel per scene when there are several.
  std::vector<std::string> arguments = {options.out_dir};
  arguments.insert(arguments.end(), csv_paths.begin(), csv_paths.end());
  std::cout << run_figure_script("convergence_figure.py", arguments).message << "\n";
}

void add_convergence_options(CLI::App& cmd, ConvergenceOptions& options) {
  cmd.add_option("scene", options.scene_paths, "Scene file(s) (TOML), e.g. scenes/studies/scenario2.toml")
      ->required();
  cmd.add_option("--set", options.overrides, "Override a scene key in every scene: section.key=value (repeatable)");
  cmd.add_option("--out", options.out_dir, "Output folder")->capture_default_str();
  cmd.add_option("--repeats", options.repeats, "Runs per setting; the wall time is their median")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  cmd.add_flag("!--no-figures", options.figures, "Skip the figures");
  add_jobs_option(cmd, options.jobs);
}

}  // namespace

void add_convergence_study_command(CLI::App& study) {
  add_command(study, "convergence", kDescription, add_convergence_options, run_convergence);
}

}  // namespace railjoint::cli
