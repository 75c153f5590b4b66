// `railjoint validate`: the main job. Runs every scene in scenes/validation/
// through the Bullet simulation, compares the measured vertical momentum jump
// with the three analytic forms, and draws the thesis's figures 3.7, 4.3,
// 4.5, 4.6, 4.7 and 4.8 with simulated points over the analytic curves.

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "scenes/cli/command.h"
#include "scenes/cli/commands.h"
#include "scenes/cli/figure_script.h"
#include "scenes/cli/jobs_option.h"
#include "scenes/cli/output_folder.h"
#include "scenes/scene_file.h"
#include "scenes/studies/thesis_figures.h"
#include "scenes/studies/validation_study.h"
#include "scenes/studies/validation_table.h"
#include "support/input_error.h"
#include "support/interrupted_run.h"
#include "support/progress_meter.h"
#include "support/staging_folder.h"

namespace railjoint::cli {

namespace {

namespace fs = std::filesystem;

struct ValidationOptions {
  std::string scene_dir = std::string(RAILJOINT_SOURCE_DIR) + "/scenes/validation";
  std::string out_dir = "out/validation";
  bool figures = true;
  int jobs = available_cores();
};

constexpr const char* kDescription =
    "Main job: simulate every scene in scenes/validation/ (Bullet, kinematic mode) and compare the\n"
    "measured vertical momentum jump M (zdot+ - zdot-) with the analytic forms (exact, thesis as printed,\n"
    "small angle). Prints the table, writes it as CSV and Markdown, draws thesis figures 3.7, 4.3, 4.5,\n"
    "4.6, 4.7 and 4.8 with simulated points (56 extra runs). Exits 1 if a scene misses the 1e-4 bound against the exact form or cannot vouch for its number.";

std::vector<fs::path> scene_files(const std::string& dir) {
  std::vector<fs::path> files;
  if (!fs::is_directory(dir)) throw InputError(dir, "--scenes", "not a folder");
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.path().extension() == ".toml") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  if (files.empty()) throw InputError(dir, "--scenes", "holds no .toml scene files");
  return files;
}

void run_validation(const ValidationOptions& options) {
  const std::vector<fs::path> files = scene_files(options.scene_dir);
  const fs::path out_dir(options.out_dir);
  prepare_output_folder(out_dir, "--out");

  // Every scene read before the first run: a bad file costs no simulation.
  std::vector<Scene> scenes;
  for (const fs::path& file : files) scenes.push_back(load_scene(file.string()));
  const std::vector<ValidationRow> rows = validate_scenes(scenes, {options.jobs, "validation scenes"});
  const StudyTable table = validation_table(rows);
  std::cout << kValidationHeader << '\n' << table.aligned("  ", false) << std::flush;

  // The tables and the figures are written into staging folders and
  // published together (support/staging_folder.h): a run that fails on the
  // way (a full disk, a figure script's error) leaves the older ones as they were.
  StagingFolder tables(out_dir, "--out");
  try {
    write_output_file(tables.path() / "validation.csv", "--out", [&](std::ostream& out) { table.write_csv(out); });
    write_output_file(tables.path() / "validation.md", "--out", [&](std::ostream& out) { out << table.markdown(); });
  } catch (const InputError& error) {  // named where the user will look, not in the staging folder
    throw InputError(tables.published_text(error.file()), error.key(), error.message());
  } catch (const std::runtime_error& error) {
    throw std::runtime_error(tables.published_text(error.what()));
  }

  const ValidationSummary summary = summarize(rows);
  std::printf("\n%zu scenes, %d outside the %.0e bound; largest |error vs exact| %.1e; simulation wall time %.1f ms "
              "in all\n",
              rows.size(), summary.failures, kValidationErrorBound, summary.worst_abs_error, summary.wall_s * 1e3);

  const fs::path figure_dir = out_dir / "figures";
  std::optional<StagingFolder> figures;
  FigureResult drawn;
  if (options.figures) {
    prepare_output_folder(figure_dir, "--out");
    figures.emplace(figure_dir, "--out");
    const fs::path staged = figures->path();
    try {
      const std::vector<std::string> figure_4_5_scenes = write_thesis_figure_data(
          rows, [&](const std::string& name) { return open_output_file(staged / name, "--out"); }, options.jobs,
          show_progress);
      end_progress();
      std::vector<std::string> arguments = {staged.string()};
      arguments.insert(arguments.end(), figure_4_5_scenes.begin(), figure_4_5_scenes.end());
      drawn = run_figure_script("validation_figures.py", arguments);
    } catch (const std::runtime_error& error) {
      throw std::runtime_error(figures->published_text(error.what()));  // the file where the user will look
    }
  }
  {
    const PublishingOutputs publishing;  // a signal now waits until both folders are published
    if (figures) figures->publish_all();
    tables.publish_all();
  }
  std::printf("table: %s, %s\n", (out_dir / "validation.csv").c_str(), (out_dir / "validation.md").c_str());
  if (options.figures) {
    std::printf("%s%s\n", drawn.message.c_str(), drawn.drawn ? (": " + figure_dir.string()).c_str() : "");
  }
  if (summary.failures > 0) {
    throw std::runtime_error(std::to_string(summary.failures) + " validation scene(s) outside the bound");
  }
}

void add_validate_options(CLI::App& cmd, ValidationOptions& options) {
  cmd.add_option("--out", options.out_dir, "Output folder for the table and figures")->capture_default_str();
  cmd.add_option("--scenes", options.scene_dir, "Folder of validation scene files")->capture_default_str();
  cmd.add_flag("!--no-figures", options.figures, "Skip the figures (and their 56 extra runs)");
  add_jobs_option(cmd, options.jobs);
}

}  // namespace

void add_validate_command(CLI::App& app) {
  add_command(app, "validate", kDescription, add_validate_options, run_validation);
}

}  // namespace railjoint::cli
