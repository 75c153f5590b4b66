// `railjoint study convergence|stability`: the numerical studies. Error
// against run time over a ladder of step sizes and solver iterations, and the
// behaviour on stiff and extreme cases (scenes/studies/).

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "models/parameter_error.h"
#include "scenes/cli/commands.h"
#include "scenes/cli/output_folder.h"
#include "scenes/figure_script.h"
#include "scenes/input_error.h"
#include "scenes/scene_file.h"
#include "scenes/studies/convergence_study.h"
#include "scenes/studies/stability_study.h"
#include "sim/simulate_crossing.h"

namespace railjoint::cli {

namespace {

namespace fs = std::filesystem;

struct ConvergenceOptions {
  std::vector<std::string> scene_paths;
  std::vector<std::string> overrides;
  std::string out_dir = "out/studies";
  int repeats = 5;
  bool figures = true;
};

struct StabilityOptions {
  std::string out_dir = "out/studies";
  std::string scene_dir = study_scene_dir().string();
  bool quick = false;
  bool figures = true;
};

// Every scene is loaded and checked before the first run: a bad file or key
// fails in a second, not after minutes of the other scenes' ladders.
std::vector<Scene> load_simulable_scenes(const ConvergenceOptions& options) {
  std::vector<Scene> scenes;
  for (const std::string& path : options.scene_paths) {
    Scene scene = load_scene(path, options.overrides);
    try {
      check_simulation_inputs(scene.joint, scene.wheel, scene.sim);
    } catch (const ParameterError& error) {
      throw InputError(scene.file, error.key(), error.what());
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
  for (const Scene& scene : scenes) {
    const std::vector<ConvergenceSetting> ladder = convergence_ladder(scene.sim);
    const ConvergenceStudy study =
        run_convergence_study(scene, ladder, options.repeats, [&](std::size_t i, std::size_t n, const std::string& label) {
          show_progress(i, n, scene.name + ": " + label);
        });
    end_progress();
    const std::string csv = (fs::path(options.out_dir) / ("convergence_" + scene.name + ".csv")).string();
    write_convergence_csv(study, csv);
    csv_paths.push_back(csv);
    std::cout << convergence_report(study) << "table: " << csv << "\n\n";
    const bool any_impact = std::any_of(study.points.begin(), study.points.end(),
                                        [](const ConvergencePoint& p) { return p.impact_found; });
    if (!any_impact) without_impact.push_back(scene.file);
  }
  // No point with an error has no curve to draw: an error, not an empty plot.
  if (!without_impact.empty()) {
    std::string files;
    for (const std::string& f : without_impact) files += (files.empty() ? "" : ", ") + f;
    throw std::runtime_error("study convergence: no setting of the ladder found an impact for " + files +
                             " (see the failure column of the table)");
  }
  if (!options.figures) return;
  // One figure per scene, and one with a panel per scene when there are several.
  std::vector<std::string> arguments = {options.out_dir};
  arguments.insert(arguments.end(), csv_paths.begin(), csv_paths.end());
  std::cout << run_figure_script("convergence_figure.py", arguments).message << "\n";
}

void run_stability(const StabilityOptions& options) {
  prepare_output_folder(options.out_dir, "--out");
  const std::vector<StabilityCase> cases = stability_cases(options.scene_dir, options.quick);
  const std::vector<StabilityOutcome> outcomes =
      run_stability_study(cases, options.scene_dir, [](std::size_t i, std::size_t n, const StabilityCase& c) {
        show_progress(i, n, c.name);
      });
  end_progress();
  const std::string name = options.quick ? "stability_quick" : "stability";
  const fs::path csv = fs::path(options.out_dir) / (name + ".csv");
  const fs::path markdown = fs::path(options.out_dir) / (name + ".md");
  write_stability_csv(outcomes, csv.string());
  const std::string table = stability_markdown(outcomes);
  {
    std::ofstream out(markdown);
    if (!out) throw InputError(markdown.string(), "--out", "cannot write this file");
    out << "# Stability on stiff and extreme cases\n\n" << table;
  }
  std::cout << table << "\ntables: " << csv.string() << ", " << markdown.string() << "\n";
  if (options.figures) {
    std::cout << run_figure_script("stability_figure.py", {csv.string(), (fs::path(options.out_dir) / (name + ".png")).string()})
                     .message
              << "\n";
  }
}

}  // namespace

void add_study_command(CLI::App& app) {
  CLI::App* study = app.add_subcommand("study", "Numerical studies of the simulation: error against run time, and stability on stiff and extreme cases");
  study->require_subcommand(1);

  auto convergence = std::make_shared<ConvergenceOptions>();
  CLI::App* conv = study->add_subcommand(
      "convergence",
      "Error against run time: simulates each scene over a ladder of numerical settings -- fixed\n"
      "steps 1e-3 .. 1e-6 s (no refinement), a 1e-4 s step refined to 1e-5 .. 3e-7 s near contact,\n"
      "1 .. 100 solver iterations at the scene's steps -- and reports |error| of the vertical momentum\n"
      "jump against the exact analytic jump of the governing slice as simulated, the median wall time\n"
      "of --repeats runs, the Pareto-best settings and whether the scene's settings are among them.\n"
      "Writes convergence_<scene>.csv and .png (log-log error against wall time) into --out.");
  conv->add_option("scene", convergence->scene_paths, "Scene file(s) (TOML), e.g. scenes/studies/scenario2.toml")
      ->required();
  conv->add_option("--set", convergence->overrides, "Override a scene key in every scene: section.key=value (repeatable)");
  conv->add_option("--out", convergence->out_dir, "Output folder")->capture_default_str();
  conv->add_option("--repeats", convergence->repeats, "Runs per setting; the wall time is their median")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  conv->add_flag("!--no-figures", convergence->figures, "Skip the figures");
  conv->callback([convergence] { run_convergence(*convergence); });

  auto stability = std::make_shared<StabilityOptions>();
  CLI::App* stab = study->add_subcommand(
      "stability",
      "Stiff and extreme cases (beta -> 0, theta 1 and 89.9 deg, y_w at the transition y_t, v 1 and\n"
      "150 m/s, u0/R = 0.3, M 1 kg and 1e5 kg, preload 0 and 1e8 N, steps too large, wheels very thin\n"
      "and wide), each a modification of a base scene in scenes/studies/. Per case: error against\n"
      "the exact jump, penetration, tunnelling, lift-off, NaN/Inf, drift over the approach, and a\n"
      "verdict ok / inaccurate / unstable / rejected with the reason. Writes stability.csv, .md\n"
      "and .png into --out; prints the table, progress on stderr.");
  stab->add_option("--out", stability->out_dir, "Output folder")->capture_default_str();
  stab->add_option("--scenes", stability->scene_dir, "Folder of the base scenes")->capture_default_str()->check(CLI::ExistingDirectory);
  stab->add_flag("--quick", stability->quick, "Only a small subset (used by the tests)");
  stab->add_flag("!--no-figures", stability->figures, "Skip the figure");
  stab->callback([stability] { run_stability(*stability); });
}

}  // namespace railjoint::cli
