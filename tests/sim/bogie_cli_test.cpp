// The bogie run as a user runs it (`railjoint simulate scenes/forces/bogie.toml`):
// one JSON object per wheel, one CSV column per wheel, and a bogie on a
// track that cannot carry it refused by the key the user set.

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/run_cli.h"
#include "tests/support/scratch_dir.h"

namespace {

using railjoint::testing_support::run_railjoint;

const std::string kScene = std::string(RAILJOINT_SOURCE_DIR) + "/scenes/forces/bogie.toml";

// Two wheels 2.5 m apart at 50 m/s: the trailing one strikes 50 ms after the
// leading one (the scene's axle_spacing / speed), each well above P0; the
// leading wheel's entry is the run's own P1 and P2.
TEST(BogieCli, EachWheelHasItsOwnForces) {
  const auto r = run_railjoint("simulate " + kScene + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json j = nlohmann::json::parse(r.output);
  EXPECT_EQ(j.at("sim").at("verdict"), "ok");
  const nlohmann::json& f = j.at("sim").at("forces");
  EXPECT_EQ(f.at("vehicle"), "bogie");
  const nlohmann::json& wheels = f.at("wheels");
  ASSERT_EQ(wheels.size(), 2u);
  const double P0 = f.at("static_N").get<double>();
  for (const nlohmann::json& w : wheels) {
    EXPECT_GT(w.at("p1_N").get<double>(), 2.0 * P0);
    EXPECT_GT(w.at("p2_N").get<double>(), P0);
    EXPECT_TRUE(w.at("p2_window_covered").get<bool>());
    // Each wheel's rail-seat P2, read at the sleeper past the joint it is struck onto (x = +0.3 m):
    // above that support's static force, below its raw peak.
    EXPECT_GT(w.at("p2_rail_seat_N").get<double>(), f.at("rail_seat_static_N").get<double>());
    EXPECT_LT(w.at("p2_rail_seat_N").get<double>(), f.at("rail_seat_peak_N").get<double>());
    EXPECT_NEAR(w.at("p2_rail_seat_x_m").get<double>(), 0.3, 1e-9);
    EXPECT_GE(w.at("flights").get<int>(), 0);
  }
  // The run's own comes from the contacts' impulses over the step (F dt / dt):
  // round-off apart, the same force.
  EXPECT_NEAR(wheels[0].at("p1_N").get<double>(), f.at("p1_N").get<double>(), 1e-9 * f.at("p1_N").get<double>());
  EXPECT_NEAR(wheels[0].at("p2_N").get<double>(), f.at("p2_N").get<double>(), 1e-9 * f.at("p2_N").get<double>());
  // 2.5 m at 50 m/s; P1's place in its pulse may differ by a fraction of the 1.3 ms pulse.
  EXPECT_NEAR(wheels[1].at("p1_time_s").get<double>() - wheels[0].at("p1_time_s").get<double>(), 0.05, 1e-3);
}

TEST(BogieCli, TheCsvHasEachWheelsForce) {
  const std::filesystem::path csv = railjoint::testing_support::scratch_path("bogie.csv");
  const auto r = run_railjoint("simulate " + kScene + " --csv " + csv.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::ifstream in(csv);
  std::string header;
  std::getline(in, header);
  EXPECT_NE(header.find(",wheel0_contact_force_z_N,wheel1_contact_force_z_N"), std::string::npos) << header;
}

TEST(BogieCli, OtherTracksAreRefusedByTheKeyTheUserSet) {
  const auto track = run_railjoint("simulate " + kScene + " --set track.model=lumped");
  EXPECT_EQ(track.exit_code, 2);
  EXPECT_NE(track.output.find("key 'track.model': must be \"discrete\" with vehicle.model = \"bogie\""),
            std::string::npos)
      << track.output;
  const std::string discrete = std::string(RAILJOINT_SOURCE_DIR) + "/scenes/forces/lumped_track.toml";
  const auto vehicle = run_railjoint("simulate " + discrete + " --set vehicle.model=bogie");
  EXPECT_EQ(vehicle.exit_code, 2);
  EXPECT_NE(vehicle.output.find("key 'vehicle.model': \"bogie\" needs track.model = \"discrete\""), std::string::npos)
      << vehicle.output;
  const auto spacing = run_railjoint("simulate " + kScene + " --set joint.length=5");
  EXPECT_EQ(spacing.exit_code, 2);
  EXPECT_NE(spacing.output.find("key 'joint.length': must be >="), std::string::npos) << spacing.output;
}

}  // namespace
