// `railjoint simulate` in the default kinematic mode, run as a user runs it:
// the JSON keys the issue promises, the analytic block identical to
// `railjoint analytic --json`, the CSV time series, and bad [sim] input
// refused with one line naming the file and the key.

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/run_cli.h"

namespace {

namespace fs = std::filesystem;
using railjoint::testing_support::default_scene_path;
using railjoint::testing_support::run_railjoint;

TEST(SimulateCli, JsonHasTheAnalyticBlockTheSimulationAndTheErrors) {
  const auto r = run_railjoint("simulate " + default_scene_path() + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json j = nlohmann::json::parse(r.output);
  for (const char* key : {"impulse", "impact_time", "impact_x", "max_penetration", "wall_seconds", "steps"}) {
    EXPECT_TRUE(j.at("sim").contains(key)) << key;
  }
  // error = (simulated - form) / form, signed, for each form.
  const double simulated = j.at("sim").at("impulse").get<double>();
  for (const char* form : {"exact", "thesis", "small_angle"}) {
    const double analytic = j.at("analytic").at("impulse").at(form).get<double>();
    EXPECT_NEAR(j.at("error").at(form).get<double>(), (simulated - analytic) / analytic, 1e-12) << form;
  }
  // The simulated thin disc is a 1 mm cylinder: its governing slice is 0.5 mm
  // inside y_w (DESIGN: the inner face governs), and its analytic block is
  // that wheel's; the scene's thin disc has its own block.
  EXPECT_NEAR(j.at("analytic").at("governing_y").get<double>(), 0.0145, 1e-12);
  EXPECT_NEAR(j.at("sim").at("simulated_width").get<double>(), 1e-3, 1e-15);

  const auto a = run_railjoint("analytic " + default_scene_path() + " --json");
  ASSERT_EQ(a.exit_code, 0) << a.output;
  EXPECT_EQ(j.at("analytic_thin_disc"), nlohmann::json::parse(a.output)) << "same model, same numbers";
  // |error| of the default scene: observed -0.015 %; the 0.5 % target bounds it.
  EXPECT_LE(std::abs(j.at("error").at("exact").get<double>()), 5e-3);
}

TEST(SimulateCli, CsvHasOneRowPerRecordedStep) {
  const fs::path csv = fs::path(testing::TempDir()) / "simulate_cli.csv";
  const auto r = run_railjoint("simulate " + default_scene_path() + " --json --csv " + csv.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json j = nlohmann::json::parse(r.output);
  std::ifstream in(csv);
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header.rfind("t_s,x_m,z_m,zdot_m_per_s", 0), 0u) << header;
  long long rows = 0;
  for (std::string line; std::getline(in, line);) ++rows;
  // The start state plus one sample per step.
  EXPECT_EQ(rows, j.at("sim").at("steps").get<long long>() + 1);
}

TEST(SimulateCli, BadSimKeysGetOneLineNamingFileAndKey) {
  const fs::path scene = fs::path(testing::TempDir()) / "simulate_cli_bad.toml";
  struct Case {
    const char* text;
    const char* key;
  };
  for (const Case& c : {Case{"[sim]\ntime_step = -1e-4\n", "sim.time_step"},
                        Case{"[sim]\nmargin = 0.04\n", "sim.margin"},
                        Case{"[sim]\nmode = \"fast\"\n", "sim.mode"},
                        Case{"[sim]\nno_such_key = 1\n", "sim.no_such_key"},
                        Case{"[sim]\nsolver_iterations = \"ten\"\n", "sim.solver_iterations"}}) {
    std::ofstream(scene) << c.text;
    const auto r = run_railjoint("simulate " + scene.string());
    std::cout << r.output;
    EXPECT_EQ(r.exit_code, 2) << c.text;
    EXPECT_NE(r.output.find(c.key), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(scene.filename().string()), std::string::npos) << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  }
}

}  // namespace
