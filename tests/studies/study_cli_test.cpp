// `railjoint study` run as a user runs it: the quick stability suite writes
// its tables, a bad scene is one line on stderr with exit code 2.

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "tests/support/run_cli.h"
#include "tests/support/scratch_dir.h"

namespace {

using railjoint::testing_support::RunResult;
using railjoint::testing_support::run_railjoint;

namespace fs = std::filesystem;

TEST(StudyCli, QuickStabilityWritesCsvAndMarkdown) {
  const fs::path out = railjoint::testing_support::scratch_path("study_cli_stability");
  const RunResult r = run_railjoint("study stability --quick --no-figures --out " + out.string());
  std::cout << r.output;
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("baseline_scenario2"), std::string::npos);
  EXPECT_NE(r.output.find("**ok**"), std::string::npos);
  // Issue 40, item 17: a penetration of -1e-10 um printed "| -0 |" (3 cells of the quick table).
  EXPECT_EQ(r.output.find("| -0 |"), std::string::npos) << r.output;
  ASSERT_TRUE(fs::exists(out / "stability_quick.csv"));
  ASSERT_TRUE(fs::exists(out / "stability_quick.md"));
  std::ifstream csv(out / "stability_quick.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header.rfind("case,base_scene,overrides,", 0), 0u) << header;
}

TEST(StudyCli, ConvergenceOnAMissingSceneIsAnError) {
  const RunResult r = run_railjoint("study convergence /nonexistent/scene.toml");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("scene"), std::string::npos) << r.output;
}

TEST(StudyCli, ConvergenceRejectsABadOverride) {
  const RunResult r = run_railjoint("study convergence " + std::string(RAILJOINT_SOURCE_DIR) +
                                    "/scenes/studies/scenario1.toml --set wheel.speed=-3 --no-figures --repeats 1");
  std::cout << r.output;
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("wheel.speed"), std::string::npos);
}

TEST(StudyCli, ConvergenceRefusesALevelJointBeforeAnyRun) {
  // beta = 0 has no jump: once one spurious 3e-7 N s "impact" made a Pareto
  // front of noise. Now it is refused by key, before the first rung runs.
  const RunResult r = run_railjoint("study convergence " + std::string(RAILJOINT_SOURCE_DIR) +
                                    "/scenes/studies/scenario2.toml --set joint.beta=0 --no-figures --repeats 1 --out " +
                                    railjoint::testing_support::scratch_path("level_convergence").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("key 'joint.beta': a joint without a dip (beta below 1e-7 rad) is level rail"), std::string::npos)
      << r.output;
  EXPECT_FALSE(std::filesystem::exists(railjoint::testing_support::scratch_path("level_convergence")));
}

// Issue 40, item 17: `study forces --help` named force_histories.csv; the
// study writes forces_histories.csv (forces_quick_histories.csv with
// --quick). Every file the help names is one a run writes.
TEST(StudyCli, ForcesHelpNamesTheFilesItWrites) {
  const RunResult help = run_railjoint("study forces --help");
  ASSERT_EQ(help.exit_code, 0) << help.output;
  const fs::path out = railjoint::testing_support::scratch_path("study_cli_forces");
  const RunResult r = run_railjoint("study forces --quick --no-figures --jobs 2 --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  // Every "name.csv" / ".md" / ".png" of the help, under --quick's names.
  std::istringstream words(help.output);
  int named = 0;
  for (std::string word; words >> word;) {
    while (!word.empty() && (word.back() == ',' || word.back() == ';' || word.back() == ')')) word.pop_back();
    const std::size_t dot = word.rfind('.');
    if (dot == std::string::npos || word.find('/') != std::string::npos) continue;
    const std::string suffix = word.substr(dot);
    if (suffix != ".csv" && suffix != ".md" && suffix != ".png") continue;
    if (word.rfind("forces_quick", 0) == 0 || word.rfind("...", 0) == 0) continue;  // --quick's own names
    ++named;
    if (suffix == ".png") continue;  // --no-figures
    ASSERT_EQ(word.rfind("forces", 0), 0u) << word << ": the study writes forces*";
    const std::string quick = "forces_quick" + word.substr(6);
    std::cout << word << " -> " << quick << '\n';
    EXPECT_TRUE(fs::exists(out / quick)) << word << " named by --help, " << quick << " not written";
  }
  EXPECT_GE(named, 4);
}

// `study published --help` names every file the study writes (the study
// itself runs under the label study: published_study_test.cpp).
TEST(StudyCli, PublishedHelpNamesItsTables) {
  const RunResult help = run_railjoint("study published --help");
  ASSERT_EQ(help.exit_code, 0) << help.output;
  for (const char* file : {"published.csv", "published_inputs.csv", "published_runs.csv", "published.md"}) {
    EXPECT_NE(help.output.find(file), std::string::npos) << file;
  }
}

}  // namespace
