// `railjoint analytic` run as a user runs it: exit codes, one-line errors, JSON.

#include <array>
#include <cmath>
#include <iostream>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "tests/support/run_cli.h"
#include <nlohmann/json.hpp>
#include "tests/support/scratch_dir.h"

namespace {

using railjoint::testing_support::RunResult;
using railjoint::testing_support::run_railjoint;

RunResult run(const std::string& arguments) { return run_railjoint(arguments); }

std::string scene_file(const std::string& name, const std::string& text) {
  const std::filesystem::path path = railjoint::testing_support::scratch_path(name);
  std::ofstream(path) << text;
  return path.string();
}

const std::string kDefaultScene = std::string(RAILJOINT_SOURCE_DIR) + "/scenes/default.toml";

TEST(AnalyticCli, JsonHasTheDocumentedFields) {
  const RunResult r = run("analytic " + kDefaultScene + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto j = nlohmann::json::parse(r.output);
  EXPECT_EQ(j["scenario"], 2);
  for (const char* key : {"y_t_m", "x_A_m", "alpha_rad", "governing_y_m"}) EXPECT_TRUE(j[key].is_number()) << key;
  for (const char* key : {"exact_Ns", "thesis_Ns", "small_angle_Ns"}) EXPECT_TRUE(j[key].is_number()) << key;
  EXPECT_NEAR(j["x_A_m"].get<double>(), 20.0835e-3, 1e-7);  // tests/models: thesis code gives 20.0827 mm
  EXPECT_FALSE(j.contains("units")) << "every key says its unit";
}

// The report carries the scene it ran under: its inputs (theta, beta, R, M,
// v, y_w) with the defaults it used and the rail length it derived.
TEST(AnalyticCli, JsonEchoesTheSceneItRanUnder) {
  const RunResult r = run("analytic " + kDefaultScene + " --json --set wheel.speed=30");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto scene = nlohmann::json::parse(r.output).at("scene");
  std::cout << scene.dump() << '\n';
  EXPECT_EQ(scene.at("file"), kDefaultScene);
  EXPECT_EQ(scene.at("name"), "default");
  EXPECT_EQ(scene.at("joint").at("theta_deg"), 30.0);
  EXPECT_EQ(scene.at("joint").at("beta"), 0.03);
  EXPECT_EQ(scene.at("wheel").at("radius"), 0.475);
  EXPECT_EQ(scene.at("wheel").at("mass"), 750.0);
  EXPECT_EQ(scene.at("wheel").at("speed"), 30.0);  // the --set value
  EXPECT_EQ(scene.at("wheel").at("y"), 0.015);
  EXPECT_EQ(scene.at("joint").at("depth"), 0.05);  // a default the file leaves out
  EXPECT_EQ(scene.at("derived"), nlohmann::json::array({"joint.length"}));
  EXPECT_GE(scene.at("joint").at("length").get<double>(), 1.0);
}

TEST(AnalyticCli, StepSceneAndSquareJointViaSet) {
  RunResult r = run("analytic " + kDefaultScene + " --json --set joint.kind=step --set wheel.y=0");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(nlohmann::json::parse(r.output)["scenario"], "step");
  r = run("analytic " + kDefaultScene + " --json --set joint.theta_deg=90");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto j = nlohmann::json::parse(r.output);
  EXPECT_EQ(j["scenario"], 1);
  EXPECT_TRUE(j["y_t_m"].is_null()) << "infinite transition value of a square joint";
}

TEST(AnalyticCli, SummaryAndCsv) {
  const std::string csv = railjoint::testing_support::scratch_path("history.csv").string();
  const RunResult r = run("analytic " + kDefaultScene + " --csv " + csv + " --samples 11");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("scenario 2"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("N s"), std::string::npos);
  std::ifstream in(csv);
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header, "t_s,x_m,z_exact_m,zdot_exact_m_per_s,z_linear_m,zdot_linear_m_per_s,momentum_exact_Ns,impulse_exact_Ns");
  // The outputs' convention (scenes/report/outputs.md): t = 0 when the centre
  // passes the predicted impact position, x and z in the joint frame.
  const auto j = nlohmann::json::parse(run("analytic " + kDefaultScene + " --json").output);
  const double impact_x = j.at("impact_x_m").get<double>();
  const double impact_z = j.at("impact_z_m").get<double>();
  int lines = 1;
  for (std::string line; std::getline(in, line);) {
    ++lines;
    std::istringstream cells(line);
    double t = 0, x = 0, z = 0, zdot = 0;
    char comma = 0;
    cells >> t >> comma >> x >> comma >> z >> comma >> zdot;
    EXPECT_NEAR(x, impact_x + 50.0 * t, 1e-12) << line;  // v = 50 m/s held
    // Before the impact the centre descends the incoming slope at zdot, so z
    // there is the impact's height plus what is left to descend.
    if (t < 0) {
      EXPECT_NEAR(z, impact_z + zdot * t, 1e-11) << line;  // 12 digits printed
    }
  }
  EXPECT_EQ(lines, 12);  // header + 11 samples
}

// Every bad input exits non-zero with one line naming the file, the key and the range.
struct BadInput {
  const char* label;
  const char* scene_text;
  const char* expected;
};

// Test names in ctest's list: the case name, not the struct's bytes.
void PrintTo(const BadInput& c, std::ostream* out) { *out << c.label; }

class AnalyticCliBadInput : public testing::TestWithParam<BadInput> {};

TEST_P(AnalyticCliBadInput, OneLineWithFileKeyAndRange) {
  const BadInput& bad = GetParam();
  const std::string path = scene_file(std::string(bad.label) + ".toml", bad.scene_text);
  const RunResult r = run("analytic " + path);
  std::cout << r.output;
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find(path), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(bad.expected), std::string::npos) << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
}

INSTANTIATE_TEST_SUITE_P(
    Cases, AnalyticCliBadInput,
    testing::Values(BadInput{"unknown_key", "[wheel]\nradiu = 0.4\n", "key 'wheel.radiu': unknown key"},
                    BadInput{"wrong_type", "[wheel]\nspeed = \"50\"\n", "key 'wheel.speed': must be a number"},
                    BadInput{"theta_zero", "[joint]\ntheta_deg = 0\n", "key 'joint.theta_deg': must be in (0, 90]"},
                    BadInput{"theta_big", "[joint]\ntheta_deg = 95\n", "key 'joint.theta_deg': must be in (0, 90]"},
                    BadInput{"beta_negative", "[joint]\nbeta = -0.1\n", "key 'joint.beta': must be in [0, 1]"},
                    BadInput{"y_off_head", "[wheel]\ny = -0.03\n", "key 'wheel.y': lateral position must lie"},
                    BadInput{"u0_too_big", "[joint]\nkind = \"step\"\nstep_height = 0.5\n",
                             "key 'joint.step_height': step height must satisfy |u0| < wheel.radius"},
                    BadInput{"radius_zero", "[wheel]\nradius = 0\n", "key 'wheel.radius': must be in [0.05, 10]"},
                    BadInput{"mass_negative", "[wheel]\nmass = -750\n", "key 'wheel.mass': must be in [1, 10000000]"},
                    BadInput{"mass_absurd", "[wheel]\nmass = 1e300\n", "key 'wheel.mass': must be in [1, 10000000]"},
                    BadInput{"speed_zero", "[wheel]\nspeed = 0\n", "key 'wheel.speed': must be in [0.1, 1000]"},
                    BadInput{"speed_inf", "[wheel]\nspeed = inf\n", "key 'wheel.speed': must be a finite number"},
                    BadInput{"depth_inf", "[joint]\ndepth = inf\n", "key 'joint.depth': must be a finite number"},
                    BadInput{"width_nan", "[wheel]\nwidth = nan\n", "key 'wheel.width': must be a finite number"},
                    // L_min = 0.146 m for the default joint (hand derivation in inclined_joint_test.cpp).
                    BadInput{"length_short", "[joint]\nlength = 0.1\n", "key 'joint.length': rail length L must be >= 0.146"},
                    BadInput{"length_below_cut", "[joint]\nlength = 0.01\n",
                             "key 'joint.length': rail length L must be > 2 b_t cot(theta) = 0.0692"},
                    BadInput{"gap_wide", "[joint]\nlength = 1.0\ngap = 0.5\n", "key 'joint.gap': end-post gap must be in [0, 0.465"},
                    BadInput{"crown_narrower_than_head", "[joint]\ncrown_radius = 0.01\n",
                             "key 'joint.crown_radius': crown radius must be 0 (a flat head) or > joint.half_width"},
                    BadInput{"dip_length_with_linear_dip", "[joint]\ndip_length = 0.2\n",
                             "key 'joint.dip_length': applies to dip_shape = \"quadratic\" or \"cosine\""},
                    BadInput{"conicity_steep", "[wheel]\nconicity = 1.5\n", "key 'wheel.conicity': must be in (-1, 1)"},
                    BadInput{"radius_tiny", "[wheel]\nradius = 1e-4\n", "key 'wheel.radius': must be in [0.05, 10]"}),
    [](const testing::TestParamInfo<BadInput>& param_info) { return param_info.param.label; });

// Issue 15 row 11: the thesis's section-3.2.2 example, as printed there, was
// refused ("rail length L must be >= 1.549 m"): analytic needs no rail length.
TEST(AnalyticCli, TheThesissStepExampleNeedsNoRailLength) {
  const RunResult r = run("analytic " + kDefaultScene +
                          " --set joint.kind=step --set joint.step_height=0.3 --set wheel.radius=1 --set wheel.y=0 --json");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto j = nlohmann::json::parse(r.output);
  // Exact jump with v held, by hand: the centre pivots about the step's
  // corner at sin(alpha) = sqrt(2 R u0 - u0^2) / R, so zdot+ = v tan(alpha)
  // and Delta p = M v sqrt(2 R u0 - u0^2) / (R - u0)
  // = 750 * 50 * sqrt(0.51) / 0.7 = 38257.652 N s.
  const double expected = 750.0 * 50.0 * std::sqrt(0.51) / 0.7;
  std::cout << "exact jump " << j["exact_Ns"] << " N s, by hand " << expected << " N s\n";
  EXPECT_NEAR(j["exact_Ns"].get<double>(), expected, 1e-9 * expected);
}

TEST(AnalyticCli, AClosedFormWithoutARealValueIsShownAsSuch) {
  // Eq. 3.6 as printed divides by sqrt(R^2 - 2 R u0): no real value for
  // u0 > R/2 (here 0.3 > 0.2375 m). The summary says so instead of "-nan"; the
  // JSON has null; the exact form still has its value.
  const std::string path = scene_file("tall_step.toml", "[joint]\nkind = \"step\"\nstep_height = 0.3\nlength = 3\n"
                                                        "[wheel]\ny = 0\n");
  RunResult r = run("analytic " + path);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output.find("nan"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("the printed form has no real value here"), std::string::npos) << r.output;
  r = run("analytic " + path + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto j = nlohmann::json::parse(r.output);
  EXPECT_TRUE(j["thesis_Ns"].is_null());
  EXPECT_GT(j["exact_Ns"].get<double>(), 0.0);
}

TEST(AnalyticCli, ALevelJointShowsNoJumpAndNoPercentages) {
  const RunResult r = run("analytic " + kDefaultScene + " --set joint.beta=0");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("level joint: no jump"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("%"), std::string::npos) << r.output;
}

TEST(AnalyticCli, UnreadableFile) {
  const std::string path = scene_file("unreadable.toml", "[wheel]\n");
  std::filesystem::permissions(path, std::filesystem::perms::none);
  const RunResult r = run("analytic " + path);
  // Root can read anything; then the file parses and the command succeeds.
  if (r.exit_code == 0) GTEST_SKIP() << "running as root: permissions do not stop reading";
  EXPECT_NE(r.output.find(path), std::string::npos) << r.output;
}

TEST(AnalyticCli, MissingFileIsRejectedByName) {
  const RunResult r = run("analytic /nonexistent/scene.toml");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.output, "railjoint: error: /nonexistent/scene.toml: no such scene file\n");
}

TEST(AnalyticCli, AFolderIsNotASceneFile) {
  const RunResult r = run("analytic /tmp");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.output, "railjoint: error: /tmp: is not a file (a scene is a .toml file)\n");
}

TEST(AnalyticCli, AnOverrideThatIsNoNumberIsNotTakenAsText) {
  // 1e400 overflows a double: toml++ refuses it, and it must not become the string "1e400".
  const RunResult r = run("analytic " + scene_file("plain.toml", "") + " --set wheel.speed=1e400");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("key 'wheel.speed': --set value \"1e400\" is not a valid number"), std::string::npos)
      << r.output;
}

}  // namespace

// Real geometry from the command line: the 60E1 head by name (also as
// --set joint.rail_profile=60E1, which TOML reads as the number 600), a
// measured head and tread from files beside the scene, and their faults
// named by key and file.
TEST(AnalyticCli, RealGeometryKeysAndProfileFiles) {
  const RunResult named = run("analytic " + std::string(RAILJOINT_SOURCE_DIR) + "/scenes/geometry/60e1_cone.toml --json");
  ASSERT_EQ(named.exit_code, 0) << named.output;
  const auto j = nlohmann::json::parse(named.output);
  EXPECT_TRUE(j["thesis_Ns"].is_null());
  EXPECT_TRUE(j["small_angle_Ns"].is_null());
  EXPECT_NEAR(j["contact_B_m"][1].get<double>(), -7.5e-3, 0.01e-3);  // -kappa rho on 60E1's 300 mm arc
  const RunResult by_set = run("analytic " + kDefaultScene + " --set joint.rail_profile=60E1 --set joint.half_width=0.036");
  EXPECT_EQ(by_set.exit_code, 0) << by_set.output;
  EXPECT_NE(by_set.output.find("60E1 head"), std::string::npos) << by_set.output;

  // A flat head and a cylinder measured: the thesis's numbers (a cylinder 20 mm wide at y_w = 0).
  std::ostringstream head, tread;
  for (int i = -4; i <= 4; ++i) head << i * 0.005 << ",0\n";
  for (int i = -4; i <= 4; ++i) tread << i * 0.005 << ",0.475\n";
  scene_file("flat_head.csv", "y_m,z_m\n" + head.str());
  scene_file("cylinder_tread.csv", "y_m,r_m\n" + tread.str());
  const std::string measured = scene_file("measured.toml",
                                          "[joint]\nrail_profile = \"flat_head.csv\"\n"
                                          "[wheel]\nprofile = \"cylinder_tread.csv\"\nwidth = 0.02\ny = 0.0\n");
  const RunResult m = run("analytic " + measured + " --json");
  ASSERT_EQ(m.exit_code, 0) << m.output;
  EXPECT_NEAR(nlohmann::json::parse(m.output)["exact_Ns"].get<double>(), 2.0 * 750.0 * 50.0 * std::tan(0.015), 1e-9);

  const RunResult missing = run("analytic " + measured + " --set 'joint.rail_profile=\"nothere.csv\"'");
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.output.find("key 'joint.rail_profile'"), std::string::npos) << missing.output;
  EXPECT_NE(missing.output.find("nothere.csv"), std::string::npos) << missing.output;
  const RunResult twice = run("analytic " + measured + " --set wheel.radius=0.5");
  EXPECT_EQ(twice.exit_code, 2);
  EXPECT_NE(twice.output.find("key 'wheel.radius': is given by wheel.profile"), std::string::npos) << twice.output;
  const RunResult narrow = run("analytic " + measured + " --set joint.half_width=0.03");
  EXPECT_EQ(narrow.exit_code, 2);
  // The file is named: a head spanning too little may be the file's fault (another unit).
  EXPECT_NE(narrow.output.find("key 'joint.half_width': the measured head in "), std::string::npos) << narrow.output;
  EXPECT_NE(narrow.output.find(".csv spans |y| <= "), std::string::npos) << narrow.output;
}
