// One convention for a value that is not a finite number (issue 30, item 8):
// a square joint has no transition value y_t (every wheel position is
// scenario 1; y_t = R sin(beta/2) tan(theta) grows without bound as theta
// -> 90 deg). JSON writes it null, since JSON has no infinity; the sweep's
// CSV wrote "inf", which pandas and the figure scripts read differently.
// Both now leave it absent: null in JSON, an empty cell in CSV.

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <utility>
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

// Issue 40, item 6: the thesis's linearised path of a scene the thesis's
// forms do not cover (a cone on 60E1, a gap under a cylinder) was built on
// its NaN angle: `analytic --csv` wrote 1,820 (60E1 cone) and 2,182
// (cylinder_config3/4 with a 6 mm gap) "nan"/"-nan" cells, exit 0. Every CSV
// the CLI writes for these scenes holds numbers or empty cells; the linear
// path's columns are empty in every row there (thesis_Ns is null) and
// numbers on the thesis's own geometry.
TEST(NotFiniteValues, NoCsvTheCliWritesHoldsNan) {
  const std::string source = RAILJOINT_SOURCE_DIR;
  const std::vector<std::pair<std::string, std::string>> scenes = {
      {source + "/scenes/geometry/60e1_cone.toml", ""},
      {source + "/scenes/validation/cylinder_config3.toml", " --set joint.gap=0.006"},
      {source + "/scenes/validation/cylinder_config4.toml", " --set joint.gap=0.006"},
  };
  for (const auto& [scene, overrides] : scenes) {
    const std::string stem = std::filesystem::path(scene).stem().string();
    const std::vector<std::filesystem::path> files = {
        scratch_path(stem + "_history.csv"), scratch_path(stem + "_top.csv"), scratch_path(stem + "_section.csv"),
        scratch_path(stem + "_sim.csv")};
    const RunResult analytic = run_railjoint("analytic " + scene + overrides + " --csv " + files[0].string() +
                                             " --top-view " + files[1].string() + " --head-section " + files[2].string());
    ASSERT_EQ(analytic.exit_code, 0) << analytic.output;
    const RunResult simulate = run_railjoint("simulate " + scene + overrides + " --csv " + files[3].string());
    ASSERT_EQ(simulate.exit_code, 0) << simulate.output;
    for (const std::filesystem::path& file : files) {
      std::size_t not_numbers = 0;
      std::size_t cells = 0;
      for (const std::vector<std::string>& row : read_csv(file)) {
        for (const std::string& cell : row) {
          ++cells;
          if (cell.find("nan") != std::string::npos || cell.find("inf") != std::string::npos) ++not_numbers;
        }
      }
      std::cout << file.filename().string() << ": " << cells << " cells, " << not_numbers << " nan/inf\n";
      EXPECT_EQ(not_numbers, 0u) << file;
    }
    const CsvTable history = read_csv(files[0]);
    for (std::size_t row = 1; row < history.size(); ++row) {
      EXPECT_EQ(history[row][column(history, "z_linear_m")], "") << stem << " row " << row;
      EXPECT_EQ(history[row][column(history, "zdot_linear_m_per_s")], "") << stem << " row " << row;
    }
  }
  // The thesis's geometry keeps its linearised path: at the default scene's
  // last sample (after the impact) zdot = v sin(alpha_thesis), a number.
  const std::filesystem::path history = scratch_path("default_history.csv");
  ASSERT_EQ(run_railjoint("analytic " + default_scene_path() + " --csv " + history.string()).exit_code, 0);
  const CsvTable table = read_csv(history);
  EXPECT_GT(std::stod(table.back()[column(table, "zdot_linear_m_per_s")]), 0.0);
}

}  // namespace
}  // namespace railjoint
