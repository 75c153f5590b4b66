// `railjoint study inertia`: where the kinematic model stops holding. Sweeps
// the inertial simulation (wheel pressed on by its weight and the static wheel
// load only) over speed, lateral position and junction angle, finds the
// simulated lift-off speeds against the pivot model, and compares the peak
// force of a compliant contact with the P1 estimate (scenes/studies/inertia_study.h).

#include <filesystem>
#include <iostream>
#include <string>

#include "scenes/cli/command.h"
#include "scenes/cli/commands.h"
#include "scenes/cli/jobs_option.h"
#include "scenes/cli/output_folder.h"
#include "scenes/cli/figure_script.h"
#include "scenes/studies/inertia_study.h"

namespace railjoint::cli {

namespace {

namespace fs = std::filesystem;

struct InertiaOptions {
  std::string out_dir = "out/studies";
  bool quick = false;
  bool figures = true;
  std::string readme_figure;
  int jobs = available_cores();
};

constexpr const char* kDescription =
    "Where the kinematic model stops holding. The inertial simulation (sim.mode = \"inertial\": the wheel\n"
    "pressed on by its weight and a 112.5 kN wheel load, free to leave the rail; horizontal speed held,\n"
    "rigid plastic frictionless contact, a 3 m linear dip with the thesis's beta = 0.03 rad) swept over\n"
    "theta = 30/45/60/90 deg, v = 10..50 m/s and y_w = -18..18 mm: first jump at the joint, landing\n"
    "jump after a flight, total vertical impulse, lift-off, next to the exact kinematic jump. Then the\n"
    "simulated lift-off speed of the scenario-2 pivot, the step-down pivot and the dip's entry kink\n"
    "(bisection on v) against v_c = sqrt(W R cos^3(phi) / M), and the peak force of a compliant contact\n"
    "(linearised Hertz stiffness) against Jenkins et al.'s P1 for a rigid track. Writes\n"
    "inertia_sweep.csv, inertia_thresholds.csv, inertia_peaks.csv, inertia.md and inertia_*.png into\n"
    "--out; progress on stderr. About a minute; --quick: a few seconds.";

void run_inertia(const InertiaOptions& options) {
  prepare_output_folder(options.out_dir, "--out");
  const InertiaStudy study = run_inertia_study(options.quick, {options.jobs, "study inertia"});
  const fs::path dir(options.out_dir);
  write_inertia_csvs(study, [&](const std::string& name) { return open_output_file(dir / name, "--out"); });
  const std::string report = inertia_report(study);
  const fs::path markdown = dir / (options.quick ? "inertia_quick.md" : "inertia.md");
  write_output_file(markdown, "--out", [&](std::ostream& out) { out << report; });
  std::cout << report << "\ntables: " << (dir / "inertia_sweep.csv").string() << ", "
            << (dir / "inertia_thresholds.csv").string() << ", " << (dir / "inertia_peaks.csv").string() << ", "
            << markdown.string() << "\n";
  if (options.figures) {
    std::vector<std::string> arguments = {options.out_dir};
    if (!options.readme_figure.empty()) arguments.push_back(options.readme_figure);
    std::cout << run_figure_script("inertia_figure.py", arguments).message << "\n";
  }
}

void add_inertia_options(CLI::App& cmd, InertiaOptions& options) {
  cmd.add_option("--out", options.out_dir, "Output folder")->capture_default_str();
  cmd.add_flag("--quick", options.quick, "Only a small subset (used by the tests)");
  cmd.add_flag("!--no-figures", options.figures, "Skip the figures");
  add_jobs_option(cmd, options.jobs);
  cmd.add_option("--readme-figure", options.readme_figure,
                 "Also write the one-panel summary figure (PNG, < 300 KB) to this path");
}

}  // namespace

void add_inertia_study_command(CLI::App& study) {
  add_command(study, "inertia", kDescription, add_inertia_options, run_inertia);
}

}  // namespace railjoint::cli
