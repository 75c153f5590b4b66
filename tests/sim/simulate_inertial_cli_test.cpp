// `railjoint simulate` in inertial mode, run as a user runs it: the JSON
// carries every impact, the flights, the total impulse and (compliant
// contact) the peak force; a kinematic-only key in inertial mode is refused.

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

// Scenario 2 at 50 m/s on a 3 m joint: strike, 16 ms flight, landing.
std::string write_scene() {
  const fs::path path = railjoint::testing_support::scratch_path("inertial_scenario2.toml");
  std::ofstream out(path);
  out << "[joint]\ntheta_deg = 30.0\nlength = 3.0\n[wheel]\ny = 0.015\nspeed = 50.0\n"
         "[sim]\nmode = \"inertial\"\nrun_out_time = 0.02\n";
  return path.string();
}

TEST(SimulateInertialCli, JsonReportsImpactsFlightsAndTotal) {
  const auto r = run_railjoint("simulate " + write_scene() + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json j = nlohmann::json::parse(r.output);
  const nlohmann::json& sim = j.at("sim");
  EXPECT_EQ(sim.at("mode"), "inertial");
  ASSERT_EQ(sim.at("impacts").size(), 2u);  // the strike and the landing
  double sum = 0.0;
  for (const auto& impact : sim.at("impacts")) {
    EXPECT_TRUE(impact.contains("time_s") && impact.contains("x_m") && impact.contains("jump_Ns"));
    sum += impact.at("jump_Ns").get<double>();
  }
  EXPECT_TRUE(sim.at("impacts")[1].at("landing").get<bool>());
  EXPECT_TRUE(sim.at("liftoff").get<bool>());
  EXPECT_NEAR(sim.at("total_impulse_Ns").get<double>(), sum, 1e-6);
  ASSERT_EQ(sim.at("flights").size(), 1u);
  const auto& flight = sim.at("flights")[0];
  std::cout << "flight " << flight.dump() << "\n";
  // About 16 ms and 13 mm (tests/sim/inertial_crossing_test.cpp has the ballistic check).
  EXPECT_GT(flight.at("duration_s").get<double>(), 0.01);
  EXPECT_GT(flight.at("apex_height_m").get<double>(), 0.01);
  EXPECT_TRUE(sim.at("inertial").at("liftoff_model").at("predicted").get<bool>());
  EXPECT_FALSE(sim.contains("peak_force_N"));
}

// The inertial wheel's speed may change, so the CSV's t = 0 is found by
// interpolating the sample times where the centre passes the predicted
// impact position (scenes/report/outputs.md), as in the kinematic mode.
TEST(SimulateInertialCli, CsvTimeZeroIsWhereTheCentrePassesThePredictedImpact) {
  const fs::path csv = railjoint::testing_support::scratch_path("inertial_scenario2.csv");
  const auto r = run_railjoint("simulate " + write_scene() + " --json --csv " + csv.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json j = nlohmann::json::parse(r.output);
  const double impact_x = j.at("analytic").at("impact_x_m").get<double>();
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);
  double previous_t = -1, previous_x = 0;
  int crossings = 0;
  while (std::getline(in, line)) {
    std::istringstream cells(line);
    double t = 0, x = 0;
    char comma = 0;
    cells >> t >> comma >> x;
    if (previous_t < 0 && t >= 0) {
      std::cout << "t = 0 between x = " << previous_x << " and " << x << " m; impact at " << impact_x << " m\n";
      EXPECT_LE(previous_x, impact_x);
      EXPECT_GE(x, impact_x);
      ++crossings;
    }
    previous_t = t;
    previous_x = x;
  }
  EXPECT_EQ(crossings, 1);
  // The strike is measured on the same clock: at the predicted impact, within a step.
  const double strike_s = j.at("sim").at("impacts")[0].at("time_s").get<double>();
  std::cout << "strike at t = " << strike_s << " s\n";
  EXPECT_LT(std::abs(strike_s), 1e-4);
}

// The default scene gives no rail length and the default 1 m is too short
// for its 50 m/s flight (lift-off at the joint, landing ~0.85 m on: with the
// default 2 ms run-out the run needs ~0.95 m of outgoing rail, more than the
// 0.4 L the checks allow). The scene reader derives the length the
// simulation needs, so the run ends landed instead of being refused by
// joint.length (issue 15 row 11).
TEST(SimulateInertialCli, DefaultSceneWithoutALengthLandsOnDerivedRails) {
  const auto r = run_railjoint("simulate " + default_scene_path() + " --set sim.mode=inertial --json");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json sim = nlohmann::json::parse(r.output).at("sim");
  ASSERT_EQ(sim.at("impacts").size(), 2u) << sim.dump();
  EXPECT_TRUE(sim.at("impacts")[1].at("landing").get<bool>());
  ASSERT_EQ(sim.at("flights").size(), 1u);
  EXPECT_TRUE(sim.at("flights")[0].at("landed").get<bool>()) << sim.at("flights")[0].dump();

  // A length the user gives is theirs: too short is refused, never stretched.
  const auto given = run_railjoint("simulate " + default_scene_path() + " --set sim.mode=inertial --set joint.length=1");
  EXPECT_EQ(given.exit_code, 2) << given.output;
  EXPECT_NE(given.output.find("joint.length"), std::string::npos) << given.output;
}

TEST(SimulateInertialCli, CompliantContactReportsThePeakForce) {
  // Undamped, as Jenkins's P1 assumes (the scene's default damping is critical).
  const auto r = run_railjoint("simulate " + write_scene() +
                               " --json --set contact.law=linear --set contact.stiffness=1.5e9 --set contact.damping=0"
                               " --set sim.run_out_time=0.004");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json j = nlohmann::json::parse(r.output);
  // Of the order of P1 = P0 + beta v sqrt(k M) = 1.7 MN: finite and far above the 0.12 MN static load.
  const double peak = j.at("sim").at("peak_force_N").get<double>();
  std::cout << "peak " << peak << " N\n";
  EXPECT_GT(peak, 1e6);
  EXPECT_LT(peak, 3e6);
  EXPECT_TRUE(j.at("sim").at("inertial").at("compliant").contains("rigid_track_p1_N"));
  // P1 fed with beta v: P0 + 0.03 * 50 * sqrt(1.5e9 * 750), P0 = 112.5 kN + 750 kg * 9.81 m/s^2.
  const double p0 = 112.5e3 + 750.0 * 9.81;
  EXPECT_NEAR(j.at("sim").at("inertial").at("compliant").at("rigid_track_p1_beta_v_N").get<double>(),
              p0 + 0.03 * 50.0 * std::sqrt(1.5e9 * 750.0), 1e-3);
  // A force pulse has no single instant to read contact points at: null, not (0, 0, 0).
  EXPECT_TRUE(j.at("sim").at("contact_left_m").is_null()) << j.at("sim").at("contact_left_m");
}

// Issue 29, item 3: with an undamped linear contact (the old default) the
// wheel bounced on; the hint (lengthen the run) ended in flight again and
// printed the same hint. The default damping is critical now, so the run
// lands; an undamped contact is named as the cause; and a run-out the hint
// computes from the run's end lands.
TEST(SimulateInertialCli, AnInertialRunEndingInFlightGetsAHintThatLands) {
  const std::string linear = "simulate " + default_scene_path() +
                             " --set sim.mode=inertial --set contact.law=linear --set contact.stiffness=1.5e9";
  const auto damped = run_railjoint(linear);
  EXPECT_EQ(damped.exit_code, 0) << damped.output;
  EXPECT_EQ(damped.output.find("before the landing"), std::string::npos) << damped.output;

  const auto undamped = run_railjoint(linear + " --set contact.damping=0");
  EXPECT_EQ(undamped.exit_code, 1) << undamped.output;
  EXPECT_NE(undamped.output.find("the contact is underdamped (contact.damping = 0 N s/m, critical 2 sqrt(k M) = "
                                 "2.12e+06 N s/m)"),  // 2 sqrt(1.5e9 N/m x 750 kg) = 2.1213e6
            std::string::npos)
      << undamped.output;

  // A rigid contact stopped 4 ms after the impact, mid-flight (the flight
  // lasts 17 ms at 50 m/s): the hint's run-out must see the landing.
  const std::string rigid = "simulate " + default_scene_path() + " --set sim.mode=inertial";
  const auto short_run = run_railjoint(rigid + " --set sim.run_out_time=0.004");
  ASSERT_EQ(short_run.exit_code, 0) << short_run.output;
  const std::size_t at = short_run.output.find("--set sim.run_out_time=");
  ASSERT_NE(at, std::string::npos) << short_run.output;
  const std::string suggested = short_run.output.substr(at, short_run.output.find(' ', at + 6) - at);
  const auto followed = run_railjoint(rigid + " " + suggested);
  EXPECT_EQ(followed.exit_code, 0) << followed.output;
  EXPECT_EQ(followed.output.find("before the landing"), std::string::npos) << suggested << "\n" << followed.output;
}

TEST(SimulateInertialCli, ASpringTooSoftForAnImpactReportsNoPeak) {
  // k = 1e6 N/m sinks the 120 kN static load by 0.12 m and c = 1e6 N s/m is
  // 18x critical (2 sqrt(k M) = 5.5e4 N s/m): the wheel sinks into the rail
  // and no jump stands out. The peak force must be null, not 0 (-100 % vs P1),
  // and the message must not blame the time step alone.
  const auto r = run_railjoint("simulate " + write_scene() +
                               " --json --set contact.law=linear --set contact.stiffness=1e6 --set contact.damping=1e6");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  const auto [json, tail] = split_json_and_tail(r.output);
  ASSERT_FALSE(json.empty()) << r.output;
  EXPECT_NE(tail.find("or a contact so soft or damped that no jump stands out"), std::string::npos) << r.output;
  const nlohmann::json j = nlohmann::json::parse(json);
  EXPECT_FALSE(j.at("sim").at("impact_found").get<bool>());
  EXPECT_TRUE(j.at("sim").at("peak_force_N").is_null());
  EXPECT_TRUE(j.at("sim").at("inertial").at("compliant").at("peak_force_N").is_null());
}

TEST(SimulateInertialCli, KeysThatWouldChangeNothingAreErrors) {
  struct Case {
    const char* set;
    const char* key;
  };
  for (const Case& c : {Case{"--set sim.carrier_mass=1e4", "sim.carrier_mass"},  // horizontal held
                        Case{"--set sim.radius_of_gyration=0.3", "sim.radius_of_gyration"},  // no friction
                        Case{"--set contact.damping=100", "contact.damping"}}) {           // rigid contact
    const auto r = run_railjoint("simulate " + write_scene() + " " + c.set);
    EXPECT_EQ(r.exit_code, 2) << c.set << ": " << r.output;
    EXPECT_NE(r.output.find(std::string("key '") + c.key + "': only applies"), std::string::npos) << r.output;
  }
}

TEST(SimulateInertialCli, PreloadInInertialModeIsAnError) {
  const auto r = run_railjoint("simulate " + write_scene() + " --set sim.preload=1e5");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("sim.preload"), std::string::npos) << r.output;
}

}  // namespace
