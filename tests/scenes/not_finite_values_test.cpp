// One convention for a value that is not a finite number (issue 30, item 8):
// a square joint has no transition value y_t (every wheel position is
// scenario 1; y_t = R sin(beta/2) tan(theta) grows without bound as theta
// -> 90 deg). JSON writes it null, since JSON has no infinity; the sweep's
// CSV wrote "inf", which pandas and the figure scripts read differently.
// Both now leave it absent: null in JSON, an empty cell in CSV.

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/run_cli.h"
#include "tests/support/scratch_dir.h"
#include "tests/sweeps/sweep_test_support.h"

namespace railjoint {
namespace {

using testing_support::default_scene_path;
using testing_support::run_railjoint;
using testing_support::RunResult;
using testing_support::column;
using testing_support::CsvTable;
using testing_support::read_csv;
using testing_support::scratch_path;

TEST(NotFiniteValues, ASquareJointsTransitionValueIsNullInJsonAndEmptyInCsv) {
  const RunResult json_run = run_railjoint("analytic " + default_scene_path() + " --set joint.theta_deg=90 --json");
  ASSERT_EQ(json_run.exit_code, 0) << json_run.output;
  const nlohmann::json report = nlohmann::json::parse(json_run.output);
  ASSERT_TRUE(report.contains("y_t_m")) << json_run.output;
  EXPECT_TRUE(report["y_t_m"].is_null()) << json_run.output;

  const std::filesystem::path sweep = scratch_path("square_joint_sweep.toml");
  std::ofstream(sweep) << "name = \"square\"\nbase = \"" << default_scene_path()
                       << "\"\nrun = [\"analytic\"]\n[axes]\n\"joint.theta_deg\" = [45.0, 90.0]\n";
  const std::filesystem::path out = scratch_path("square_joint_out");
  const RunResult sweep_run = run_railjoint("sweep " + sweep.string() + " --out " + out.string());
  ASSERT_EQ(sweep_run.exit_code, 0) << sweep_run.output;
  const CsvTable table = read_csv(out / "results.csv");
  ASSERT_EQ(table.size(), 3u);
  const std::vector<std::string>& inclined = table[1];
  const std::vector<std::string>& square = table[2];
  const std::size_t y_t = column(table, "analytic.y_t_m");
  ASSERT_EQ(square.size(), table[0].size());
  EXPECT_EQ(square[column(table, "joint.theta_deg")], "90");
  EXPECT_EQ(square[y_t], "");
  // theta = 45 deg: y_t = R sin(beta/2) tan(theta) = 0.475 sin(0.015) = 7.1247 mm (default R, beta).
  EXPECT_NEAR(std::stod(inclined[y_t]), 0.475 * std::sin(0.015), 1e-12);
}

}  // namespace
}  // namespace railjoint
