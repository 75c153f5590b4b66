// `railjoint study forces`: P1 and P2 against speed beside Jenkins's, for a
// square joint and inclined joints in scenario 1 and 2, and the force
// histories at one speed (scenes/studies/forces_study.h).

#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "scenes/cli/command.h"
#include "scenes/cli/commands.h"
#include "scenes/cli/figure_script.h"
#include "scenes/cli/jobs_option.h"
#include "scenes/cli/output_folder.h"
#include "scenes/scene_file.h"
#include "scenes/studies/forces_study.h"

namespace railjoint::cli {

namespace {

namespace fs = std::filesystem;

struct ForcesOptions {
  std::string scene = std::string(RAILJOINT_SOURCE_DIR) + "/scenes/forces/lumped_track.toml";
  std::string out_dir = "out/studies";
  double history_speed_m_per_s = 50.0;
  bool quick = false;
  bool figures = true;
  int jobs = available_cores();
};

constexpr const char* kDescription =
    "Peak wheel-rail forces of a Hertz contact on an elastic track (a force scene: sim.mode =\n"
    "\"inertial\", contact.law = \"hertz\"; default scenes/forces/lumped_track.toml) against speed\n"
    "10-80 m/s, for a square joint (theta 90 deg, y_w 0), an inclined one in scenario 1 (45 deg, y_w 0)\n"
    "and in scenario 2 (45 deg, y_w 10 mm). P1 is the largest contact force of a run; P2 the largest\n"
    "after a zero-phase low-pass at 150 Hz (P2's 30-100 Hz pass, P1's 0.3-2 kHz do not). Beside them\n"
    "Jenkins et al.'s (1974) P1 = P0 + beta v sqrt(K_H m_T1 / (1 + m_T1/m_u)) and\n"
    "P2 = P0 + beta v sqrt(m_u/(m_u+m_T)) [1 - C_T pi / (4 sqrt(K_T (m_u+m_T)))] sqrt(K_T m_u), from\n"
    "the scene's own track (m_T1 rail mass, m_T rail + sleeper, K_T pad and ballast in series, C_T\n"
    "ballast damping) and K_H, Hertz's law linearised at P0. Writes forces.csv, forces.md,\n"
    "forces_histories.csv (every case at --history-speed) and forces.png into --out (with --quick:\n"
    "forces_quick.csv, ...); each row's overrides reproduce it with `railjoint simulate SCENE --set ...`.";

void run_forces(const ForcesOptions& options) {
  // Checked before any folder is made: a scene that is no force run would
  // give a table of refused rows.
  check_force_scene(load_scene(options.scene));
  prepare_output_folder(options.out_dir, "--out");
  const std::vector<ForceStudyCase> cases = force_study_cases(options.quick);
  const std::vector<ForceStudyOutcome> outcomes =
      run_force_study(options.scene, cases, options.history_speed_m_per_s, {options.jobs, "study forces"});
  const std::string name = options.quick ? "forces_quick" : "forces";
  const fs::path csv = fs::path(options.out_dir) / (name + ".csv");
  const fs::path histories = fs::path(options.out_dir) / (name + "_histories.csv");
  const fs::path markdown = fs::path(options.out_dir) / (name + ".md");
  const StudyTable forces = force_study_table(outcomes);
  const std::string table = forces.markdown();
  write_output_file(csv, "--out", [&](std::ostream& out) { forces.write_csv(out); });
  write_output_file(histories, "--out", [&](std::ostream& out) { write_force_histories_csv(outcomes, out); });
  write_output_file(markdown, "--out", [&](std::ostream& out) {
    out << "# Peak forces on an elastic track against Jenkins et al.\n\n" << table;
  });
  std::cout << table << "\ntables: " << csv.string() << ", " << histories.string() << ", " << markdown.string()
            << "\n";
  if (options.figures) {
    std::cout << run_figure_script("forces_figure.py", {csv.string(), histories.string(),
                                                        (fs::path(options.out_dir) / (name + ".png")).string()})
                     .message
              << "\n";
  }
}

void add_forces_options(CLI::App& cmd, ForcesOptions& options) {
  cmd.add_option("--scene", options.scene, "Base force scene (TOML)")->capture_default_str()->check(CLI::ExistingFile);
  cmd.add_option("--out", options.out_dir, "Output folder")->capture_default_str();
  cmd.add_option("--history-speed", options.history_speed_m_per_s,
                 "Speed whose force histories are written and drawn [m/s] (one of the study's speeds)")
      ->capture_default_str();
  cmd.add_flag("--quick", options.quick, "Only 30 and 50 m/s (used by the tests)");
  cmd.add_flag("!--no-figures", options.figures, "Skip the figure");
  add_jobs_option(cmd, options.jobs);
}

}  // namespace

void add_forces_study_command(CLI::App& study) {
  add_command(study, "forces", kDescription, add_forces_options, run_forces);
}

}  // namespace railjoint::cli
