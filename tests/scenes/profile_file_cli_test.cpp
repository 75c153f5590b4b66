// Measured profile files through a scene, as a user runs them (issue 40,
// items 4 and 5): the unit in the header, the millimetre file refused by
// its key, the smoothing's key and its report.

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/run_cli.h"
#include "tests/support/scratch_dir.h"

namespace {

using railjoint::testing_support::RunResult;
using railjoint::testing_support::run_railjoint;

std::string scratch_file(const std::string& name, const std::string& text) {
  const std::filesystem::path path = railjoint::testing_support::scratch_path(name);
  std::ofstream(path) << text;
  return path.string();
}

// A 300 mm crown every `spacing_m` across +-36 mm, in metres times `scale`,
// heights rounded to `round_m` (0: exact).
std::string crown_points(double spacing_m, double scale, double round_m = 0.0) {
  std::ostringstream csv;
  csv.precision(17);
  const int n = static_cast<int>(std::lround(0.072 / spacing_m));
  for (int i = 0; i <= n; ++i) {
    const double y = -0.036 + 0.072 * i / n;
    double z = std::sqrt(0.09 - y * y) - 0.3;
    if (round_m > 0.0) z = std::round(z / round_m) * round_m;
    csv << y * scale << ',' << z * scale << '\n';
  }
  return csv.str();
}

// The 60e1_cone scene's joint and wheel on a measured head.
std::string head_scene(const std::string& name, const std::string& csv, const std::string& more = "") {
  return scratch_file(name, "[joint]\ntheta_deg = 30.0\nbeta = 0.03\nhalf_width = 0.036\nrail_profile = \"" + csv +
                                "\"\n" + more + "[wheel]\nwidth = 0.07\ny = 0.0\nconicity = 0.025\n");
}

double exact_Ns(const RunResult& r) { return nlohmann::json::parse(r.output)["exact_Ns"].get<double>(); }

TEST(ProfileFileCli, MillimetresNeedTheirHeader) {
  scratch_file("crown_m.csv", "y,z\n" + crown_points(5e-4, 1.0));
  scratch_file("crown_mm.csv", "y,z\n" + crown_points(5e-4, 1e3));
  scratch_file("crown_mm_named.csv", "y_mm,z_mm\n" + crown_points(5e-4, 1e3));
  const RunResult metres = run_railjoint("analytic " + head_scene("m.toml", "crown_m.csv") + " --json");
  ASSERT_EQ(metres.exit_code, 0) << metres.output;
  // Read as metres it ran at 1664.73 N s against 1275.25 N s, exit 0.
  const RunResult mm = run_railjoint("analytic " + head_scene("mm.toml", "crown_mm.csv"));
  EXPECT_EQ(mm.exit_code, 2) << mm.output;
  EXPECT_NE(mm.output.find("key 'joint.rail_profile'"), std::string::npos) << mm.output;
  EXPECT_NE(mm.output.find("crown_mm.csv: line 2: y = -36"), std::string::npos) << mm.output;
  EXPECT_NE(mm.output.find("y_mm,z_mm"), std::string::npos) << mm.output;
  const RunResult named = run_railjoint("analytic " + head_scene("mm_named.toml", "crown_mm_named.csv") + " --json");
  ASSERT_EQ(named.exit_code, 0) << named.output;
  EXPECT_NEAR(exact_Ns(named), exact_Ns(metres), 1e-9 * exact_Ns(metres));
  // The text report names the file.
  const RunResult text = run_railjoint("analytic " + head_scene("m.toml", "crown_m.csv"));
  EXPECT_NE(text.output.find("measured head " + railjoint::testing_support::scratch_path("crown_m.csv").string()),
            std::string::npos)
      << text.output;
}

TEST(ProfileFileCli, TheToleranceKeyAndTheSmoothingReport) {
  scratch_file("crown_rounded.csv", "y,z\n" + crown_points(1e-5, 1.0, 1e-6));
  const std::string scene = head_scene("rounded.toml", "crown_rounded.csv");
  const RunResult smoothed = run_railjoint("analytic " + scene + " --json");
  ASSERT_EQ(smoothed.exit_code, 0) << smoothed.output;
  const auto j = nlohmann::json::parse(smoothed.output)["profile_smoothing"];
  std::printf("%s\n", j.dump().c_str());
  EXPECT_EQ(j["head"]["tolerance_m"].get<double>(), 2e-6);  // the documented default
  EXPECT_EQ(j["head"]["points"].get<int>(), 7201);
  EXPECT_TRUE(j["sensitive"].get<bool>());  // through the points: 1423.66 N s, -10.5 %
  EXPECT_TRUE(j["tread"].is_null());
  const double crown =
      exact_Ns(run_railjoint("analytic " + head_scene("crown.toml", "crown_rounded.csv") +
                             " --set joint.rail_profile=crowned --set joint.crown_radius=0.3 --json"));
  EXPECT_NEAR(j["jump_Ns"].get<double>(), crown, 0.01 * crown);
  const RunResult text = run_railjoint("analytic " + scene);
  EXPECT_NE(text.output.find("WARNING: over 1 %"), std::string::npos) << text.output;

  const RunResult exact = run_railjoint("analytic " + scene + " --set joint.profile_tolerance=0 --json");
  ASSERT_EQ(exact.exit_code, 0) << exact.output;
  EXPECT_TRUE(nlohmann::json::parse(exact.output)["profile_smoothing"].is_null());
  EXPECT_NEAR(exact_Ns(exact), j["jump_unsmoothed_Ns"].get<double>(), 1e-9 * crown);

  const RunResult no_profile = run_railjoint("analytic " + std::string(RAILJOINT_SOURCE_DIR) +
                                             "/scenes/default.toml --set joint.profile_tolerance=1e-6");
  EXPECT_EQ(no_profile.exit_code, 2);
  EXPECT_NE(no_profile.output.find("key 'joint.profile_tolerance': applies to a measured rail_profile"),
            std::string::npos)
      << no_profile.output;
  const RunResult in_um = run_railjoint("analytic " + scene + " --set joint.profile_tolerance=2");
  EXPECT_EQ(in_um.exit_code, 2);
  EXPECT_NE(in_um.output.find("key 'joint.profile_tolerance'"), std::string::npos) << in_um.output;
}

}  // namespace
