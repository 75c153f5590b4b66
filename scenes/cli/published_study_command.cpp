// `railjoint study published`: published dipped-joint cases beside Jenkins's
// formula and railjoint's lumped and discrete force runs
// (scenes/studies/published_cases.h).

#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "scenes/cli/command.h"
#include "scenes/cli/commands.h"
#include "scenes/cli/jobs_option.h"
#include "scenes/cli/output_folder.h"
#include "scenes/studies/published_cases.h"

namespace railjoint::cli {

namespace {

namespace fs = std::filesystem;

struct PublishedOptions {
  std::string out_dir = "out/studies";
  int jobs = available_cores();
};

constexpr const char* kDescription =
    "Published dipped-joint cases rerun: the peer calculator's worked example (P0 100 kN, 2 alpha 0.02,\n"
    "30 m/s, K_H 1.4e9 N/m, m_T1 500, m_u 350, m_T 800 kg, K_T 4e7 N/m, C_T 2e4 N s/m; published P1\n"
    "422.1 kN), the standard's (GM/TT0088) track as commonly quoted (2 alpha 0.02, m_T 245 kg, K_T\n"
    "150 MN/m, C_T 55.4 kN s/m; P0 100 kN, m_u 1000 kg, 40 m/s assumed) with K_T split three ways\n"
    "between pad and ballast, and Bjork's (1970) unsprung-mass trend (4200 -> 1700 kg per axle cut the\n"
    "dynamic increment some 40 %). Each beside Jenkins's formula as railjoint computes it (P2 with\n"
    "GM/TT0088's quarter-period damping bracket and with the calculator's), railjoint's force runs on\n"
    "scenes/forces/lumped_track.toml (the contact's P2 and the rail seat's) and on\n"
    "scenes/forces/discrete_track.toml (its supports chosen so that its lumped reading has the case's\n"
    "K_T, m_T and C_T), and why they differ. Forces in kN, the trend in %. Writes published.csv (the\n"
    "comparison), published_inputs.csv (every input, published with its source or assumed),\n"
    "published_runs.csv (each force run's --set overrides and numbers) and published.md into --out.\n"
    "Exit 0; 1 when a run cannot vouch for its result or was refused (the table says which).";

bool all_vouched(const std::vector<PublishedOutcome>& outcomes) {
  for (const PublishedOutcome& o : outcomes) {
    for (const PublishedSettingOutcome& s : o.settings) {
      if (!s.lumped.ran || s.lumped.verdict != "ok" || !s.discrete.ran || s.discrete.verdict != "ok") return false;
    }
  }
  return true;
}

void run_published(const PublishedOptions& options) {
  prepare_output_folder(options.out_dir, "--out");
  const std::vector<PublishedOutcome> outcomes = run_published_study(published_cases(), {options.jobs, "study published"});
  const fs::path csv = fs::path(options.out_dir) / "published.csv";
  const fs::path inputs = fs::path(options.out_dir) / "published_inputs.csv";
  const fs::path runs = fs::path(options.out_dir) / "published_runs.csv";
  const fs::path markdown = fs::path(options.out_dir) / "published.md";
  const std::string table = published_markdown(outcomes);
  write_output_file(csv, "--out", [&](std::ostream& out) { published_table(outcomes).write_csv(out); });
  write_output_file(inputs, "--out", [&](std::ostream& out) { write_published_inputs_csv(outcomes, out); });
  write_output_file(runs, "--out", [&](std::ostream& out) { write_published_runs_csv(outcomes, out); });
  write_output_file(markdown, "--out",
                    [&](std::ostream& out) { out << "# Published dipped-joint cases rerun\n\n" << table; });
  std::cout << table << "\ntables: " << csv.string() << ", " << inputs.string() << ", " << runs.string() << ", "
            << markdown.string() << "\n";
  if (!all_vouched(outcomes)) {
    throw std::runtime_error("study published: not every force run could vouch for its result (the verdict column "
                             "of " + runs.string() + ")");
  }
}

void add_published_options(CLI::App& cmd, PublishedOptions& options) {
  cmd.add_option("--out", options.out_dir, "Output folder")->capture_default_str();
  add_jobs_option(cmd, options.jobs);
}

}  // namespace

void add_published_study_command(CLI::App& study) {
  add_command(study, "published", kDescription, add_published_options, run_published);
}

}  // namespace railjoint::cli
