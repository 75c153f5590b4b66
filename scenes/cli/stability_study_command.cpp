// `railjoint study stability`: stiff and extreme cases, each with a verdict
// and its reason (scenes/studies/stability_study.h).

#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "scenes/cli/command.h"
#include "scenes/cli/commands.h"
#include "scenes/cli/jobs_option.h"
#include "scenes/cli/output_folder.h"
#include "scenes/cli/figure_script.h"
#include "scenes/studies/stability_study.h"

namespace railjoint::cli {

namespace {

namespace fs = std::filesystem;

struct StabilityOptions {
  std::string out_dir = "out/studies";
  std::string scene_dir = study_scene_dir().string();
  bool quick = false;
  bool figures = true;
  int jobs = available_cores();
};

constexpr const char* kDescription =
    "Stiff and extreme cases (beta -> 0, theta 1 and 89.9 deg, y_w at the transition y_t, v 1 and\n"
    "150 m/s, u0/R = 0.3, M 1 kg and 1e5 kg, preload 0 and 1e8 N, steps too large, wheels very thin\n"
    "and wide), each a modification of a base scene in scenes/studies/. Per case: error against\n"
    "the exact jump, penetration, tunnelling, lift-off, NaN/Inf, drift over the approach, and a\n"
    "verdict ok / inaccurate / unstable / rejected with the reason. Writes stability.csv, .md\n"
    "and .png into --out; prints the table, progress on stderr.";

void run_stability(const StabilityOptions& options) {
  prepare_output_folder(options.out_dir, "--out");
  const std::vector<StabilityCase> cases = stability_cases(options.scene_dir, options.quick);
  const std::vector<StabilityOutcome> outcomes =
      run_stability_study(cases, options.scene_dir, {options.jobs, "study stability"});
  const std::string name = options.quick ? "stability_quick" : "stability";
  const fs::path csv = fs::path(options.out_dir) / (name + ".csv");
  const fs::path markdown = fs::path(options.out_dir) / (name + ".md");
  const std::string table = stability_markdown(outcomes);
  write_output_file(csv, "--out", [&](std::ostream& out) { stability_table(outcomes).write_csv(out); });
  write_output_file(markdown, "--out",
                    [&](std::ostream& out) { out << "# Stability on stiff and extreme cases\n\n" << table; });
  std::cout << table << "\ntables: " << csv.string() << ", " << markdown.string() << "\n";
  if (options.figures) {
    std::cout << run_figure_script("stability_figure.py", {csv.string(), (fs::path(options.out_dir) / (name + ".png")).string()})
                     .message
              << "\n";
  }
}

void add_stability_options(CLI::App& cmd, StabilityOptions& options) {
  cmd.add_option("--out", options.out_dir, "Output folder")->capture_default_str();
  cmd.add_option("--scenes", options.scene_dir, "Folder of the base scenes")->capture_default_str()->check(CLI::ExistingDirectory);
  cmd.add_flag("--quick", options.quick, "Only a small subset (used by the tests)");
  cmd.add_flag("!--no-figures", options.figures, "Skip the figure");
  add_jobs_option(cmd, options.jobs);
}

}  // namespace

void add_stability_study_command(CLI::App& study) {
  add_command(study, "stability", kDescription, add_stability_options, run_stability);
}

}  // namespace railjoint::cli
