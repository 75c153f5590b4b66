// `railjoint simulate` in the default kinematic mode, run as a user runs it:
// the JSON keys the issue promises, the `analytic` block identical to
// `railjoint analytic --json`, errors against the wheel as simulated, the CSV time series, and bad [sim] input
// refused with one line naming the file and the key.

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/run_cli.h"
#include "tests/support/scratch_dir.h"

namespace {

namespace fs = std::filesystem;
using railjoint::testing_support::default_scene_path;
using railjoint::testing_support::run_railjoint;
using railjoint::testing_support::split_json_and_tail;

TEST(SimulateCli, JsonHasTheAnalyticBlockTheSimulationAndTheErrors) {
  const auto r = run_railjoint("simulate " + default_scene_path() + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json j = nlohmann::json::parse(r.output);
  for (const char* key : {"impulse_Ns", "impact_time_s", "impact_x_m", "max_penetration_m", "wall_time_s", "steps"}) {
    EXPECT_TRUE(j.at("sim").contains(key)) << key;
  }
  // The contract: `analytic` is the block of `railjoint analytic --json`.
  const auto a = run_railjoint("analytic " + default_scene_path() + " --json");
  ASSERT_EQ(a.exit_code, 0) << a.output;
  nlohmann::json analytic_report = nlohmann::json::parse(a.output);
  EXPECT_EQ(analytic_report.at("scene"), j.at("scene")) << "the same scene, echoed once at the top";
  analytic_report.erase("scene");
  EXPECT_EQ(j.at("analytic"), analytic_report) << "same model, same numbers";
  // The simulated thin disc is a 1 mm cylinder reaching outward from y_w, so
  // its governing slice, the inner face, lies in the disc's plane (sim/setting_checks.h).
  EXPECT_NEAR(j.at("analytic_as_simulated").at("governing_y_m").get<double>(), 0.015, 1e-12);
  EXPECT_NEAR(j.at("sim").at("simulated_width_m").get<double>(), 1e-3, 1e-15);
  // error = (simulated - form) / form, signed, for each form.
  const double simulated = j.at("sim").at("impulse_Ns").get<double>();
  for (const char* form : {"exact", "thesis", "small_angle"}) {
    const double analytic = j.at("analytic_as_simulated").at(std::string(form) + "_Ns").get<double>();
    EXPECT_NEAR(j.at("error").at(form).get<double>(), (simulated - analytic) / analytic, 1e-12) << form;
  }
  // So the measured jump is the scene's thin disc's (2149.5 N s, the
  // thesis's figure-4.5 point): observed +2.4e-5; 1e-4 is the target.
  const double scene_exact = j.at("analytic").at("exact_Ns").get<double>();
  EXPECT_NEAR(scene_exact, 2149.498, 1e-3);
  EXPECT_NEAR(simulated, scene_exact, 1e-4 * scene_exact);
  EXPECT_NEAR(j.at("error_vs_scene_wheel").at("exact").get<double>(), (simulated - scene_exact) / scene_exact, 1e-12);
  // |error| of the default scene: observed -0.015 %; the 0.5 % target bounds it.
  EXPECT_LE(std::abs(j.at("error").at("exact").get<double>()), 5e-3);
}

TEST(SimulateCli, NoImpactGivesNullsAndAFailingExitCode) {
  // A fixed 3 ms step carries the wheel 150 mm: over the joint without ever
  // resolving the strike (the stability study's fixed_step_3e-3 case).
  const auto r = run_railjoint("simulate " + default_scene_path() +
                               " --json --set sim.time_step=3e-3 --set sim.refined_time_step=3e-3");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  // stdout holds the JSON, then stderr's one line says why the run failed.
  const auto [json, tail] = split_json_and_tail(r.output);
  ASSERT_FALSE(json.empty()) << r.output;
  EXPECT_NE(tail.find("found no impact at the joint"), std::string::npos) << r.output;
  const nlohmann::json j = nlohmann::json::parse(json);
  EXPECT_FALSE(j.at("sim").at("impact_found").get<bool>());
  EXPECT_TRUE(j.at("sim").at("impulse_Ns").is_null());
  for (const char* form : {"exact", "thesis", "small_angle"}) EXPECT_TRUE(j.at("error").at(form).is_null()) << form;
}

TEST(SimulateCli, ALevelJointIsRefusedByKey) {
  // No dip, no jump: a run could only measure noise.
  const auto r = run_railjoint("simulate " + default_scene_path() + " --set joint.beta=0");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("key 'joint.beta'"), std::string::npos) << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
}

TEST(SimulateCli, AThinDiscOnTheRailHeadEdgeIsRefused) {
  // Measured before the rule: y = -19.5 mm gave -58 % (a contact at the start),
  // +19.5 mm +1.5 %; the stand-in cylinder is 1 mm wide, so |y| <= 19 mm.
  for (const char* y : {"-0.0195", "0.0195", "0.02"}) {
    const auto r = run_railjoint("simulate " + default_scene_path() + " --set wheel.y=" + y);
    EXPECT_EQ(r.exit_code, 2) << y << ": " << r.output;
    EXPECT_NE(r.output.find("key 'wheel.y': for the simulation a thin disc"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("|y| <= joint.half_width - 2 sim.disc_half_width = 0.019 m"), std::string::npos)
        << r.output;
  }
  // At the limit, both sides, the jump is within the 0.5 % of the validation;
  // on a 30 mm head the limit 0.03 - 0.001 is not 0.029 in binary, and 0.029 must pass.
  for (const char* sets : {"--set wheel.y=-0.019", "--set wheel.y=0.019",
                           "--set joint.half_width=0.03 --set wheel.y=0.029"}) {
    const auto r = run_railjoint("simulate " + default_scene_path() + " --json " + sets);
    const char* y = sets;
    ASSERT_EQ(r.exit_code, 0) << y << ": " << r.output;
    EXPECT_LT(std::abs(nlohmann::json::parse(r.output).at("error").at("exact").get<double>()), 0.005) << y;
  }
}

TEST(SimulateCli, CsvHasOneRowPerRecordedStep) {
  const fs::path csv = railjoint::testing_support::scratch_path("simulate_cli.csv");
  const auto r = run_railjoint("simulate " + default_scene_path() + " --json --csv " + csv.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json j = nlohmann::json::parse(r.output);
  std::ifstream in(csv);
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header.rfind("t_s,x_m,z_m,zdot_m_per_s", 0), 0u) << header;
  // t = 0 where the centre passes the predicted impact position (as in
  // `analytic --csv`), the run starting at sim.start_time_s on that clock.
  const double impact_x = j.at("analytic").at("impact_x_m").get<double>();
  long long rows = 0;
  double previous_t = 0, previous_x = 0;
  for (std::string line; std::getline(in, line);) {
    std::istringstream cells(line);
    double t = 0, x = 0;
    char comma = 0;
    cells >> t >> comma >> x;
    if (rows == 0) {
      EXPECT_DOUBLE_EQ(t, j.at("sim").at("start_time_s").get<double>());
    }
    if (rows > 0 && previous_t < 0 && t >= 0) {
      std::cout << "t = 0 between x = " << previous_x << " and " << x << " m; impact at " << impact_x << " m\n";
      EXPECT_LE(previous_x, impact_x);
      EXPECT_GE(x, impact_x);
    }
    previous_t = t;
    previous_x = x;
    ++rows;
  }
  // The start state plus one sample per step.
  EXPECT_EQ(rows, j.at("sim").at("steps").get<long long>() + 1);
}

TEST(SimulateCli, BadSimKeysGetOneLineNamingFileAndKey) {
  const fs::path scene = railjoint::testing_support::scratch_path("simulate_cli_bad.toml");
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

// The text report's times are the JSON's: one clock for every output,
// t = 0 when the centre passes the predicted impact (scenes/report/outputs.md).
// Found by an independent audit: the text printed the run's own clock, 1 ms
// later on these scenes (their 50 mm approach at 50 m/s: P1 1.9498 ms in the
// text against 0.94981 ms in the JSON, the kinematic impact 1.000000 ms
// against -1.7e-12 s). Each is compared to the digits the text prints.
TEST(SimulateCli, TheTextReportsTimesAreTheJsonsClock) {
  // The first time "at t = <number>" on the first line of `text` that starts with `line_start`.
  const auto time_on_line = [](const std::string& text, const std::string& line_start) {
    for (std::size_t at = 0; at < text.size();) {
      const std::size_t end = std::min(text.find('\n', at), text.size());
      const std::string line = text.substr(at, end - at);
      const std::size_t t = line.find("at t = ");
      if (line.rfind(line_start, 0) == 0 && t != std::string::npos) return std::stod(line.substr(t + 7));
      at = end + 1;
    }
    return std::nan("");
  };
  const std::string lumped = std::string(RAILJOINT_SOURCE_DIR) + "/scenes/forces/lumped_track.toml";
  const auto text = run_railjoint("simulate " + lumped);
  const auto json = run_railjoint("simulate " + lumped + " --json");
  ASSERT_EQ(text.exit_code, 0) << text.output;
  ASSERT_EQ(json.exit_code, 0) << json.output;
  const nlohmann::json sim = nlohmann::json::parse(json.output).at("sim");
  const nlohmann::json& forces = sim.at("forces");
  EXPECT_NEAR(time_on_line(text.output, "  P1 "), forces.at("p1_time_s").get<double>() * 1e3, 1e-4);
  EXPECT_NEAR(time_on_line(text.output, "  P2 "), forces.at("p2_time_s").get<double>() * 1e3, 1e-4);
  EXPECT_NEAR(time_on_line(text.output, "  rail seat (pad)"),
              forces.at("rail_seat_peak_time_s").get<double>() * 1e3, 1e-4);
  EXPECT_NEAR(time_on_line(text.output, "impact at t ="), sim.at("impact_time_s").get<double>() * 1e3, 1e-6);

  const auto text_k = run_railjoint("simulate " + default_scene_path());
  const auto json_k = run_railjoint("simulate " + default_scene_path() + " --json");
  ASSERT_EQ(text_k.exit_code, 0) << text_k.output;
  ASSERT_EQ(json_k.exit_code, 0) << json_k.output;
  EXPECT_NEAR(time_on_line(text_k.output, "impact at t ="),
              nlohmann::json::parse(json_k.output).at("sim").at("impact_time_s").get<double>() * 1e3, 1e-6);
}

}  // namespace
