// `railjoint study` run as a user runs it: the quick stability suite writes
// its tables, a bad scene is one line on stderr with exit code 2.

#include <filesystem>
#include <fstream>
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

}  // namespace
