// Issue 29, item 9: "-0" in outputs. A quantity that is zero but was
// computed as -0.0 (the pressure rate while the patch is whole, a penetration
// that never happened) read as a signed value. Every file output, the
// sweep's rows and the JSON reports write it as 0.

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/no_negative_zero.h"
#include "tests/support/run_cli.h"
#include "tests/support/scratch_dir.h"

namespace railjoint {
namespace {

using testing_support::run_railjoint;
using testing_support::RunResult;
using testing_support::scratch_path;

std::string text_of(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// A cell or value that is a negative zero: -0, -0.0, -0e+00 between
// separators. (Not std::regex: GCC 12 warns falsely in <regex> under the
// sanitizer build's -O1, and warnings are errors.)
bool has_negative_zero(const std::string& text) {
  const auto separator = [](char c) { return c == ',' || c == ' ' || c == '\n' || c == '[' || c == ']' || c == ':'; };
  for (std::size_t at = text.find("-0"); at != std::string::npos; at = text.find("-0", at + 1)) {
    if (at > 0 && !separator(text[at - 1])) continue;
    std::size_t end = at + 2;
    if (end < text.size() && text[end] == '.') {
      ++end;
      while (end < text.size() && text[end] == '0') ++end;
    }
    if (end < text.size() && text[end] == 'e') {
      std::size_t exponent = end + 1;
      if (exponent < text.size() && (text[exponent] == '+' || text[exponent] == '-')) ++exponent;
      const std::size_t digits = exponent;
      while (exponent < text.size() && text[exponent] == '0') ++exponent;
      if (exponent > digits) end = exponent;
    }
    if (end == text.size() || separator(text[end])) return true;
  }
  return false;
}

TEST(NegativeZero, TheDetectorFindsOne) {
  EXPECT_TRUE(has_negative_zero("a,-0,b"));
  EXPECT_TRUE(has_negative_zero("\"rate\": -0.0,\n"));
  EXPECT_TRUE(has_negative_zero("x,-0e+00\n"));
  EXPECT_FALSE(has_negative_zero("a,-0.01,b,-1e-05,0,-0.5e3"));
}

TEST(NegativeZero, FileOutputsWriteZeroUnsigned) {
  // The pressure rate is -0.0 at every step before the patch reaches the gap.
  const std::filesystem::path pressure_csv = scratch_path("pressure.csv");
  const RunResult pressure = run_railjoint("pressure " + std::string(RAILJOINT_SOURCE_DIR) +
                                           "/scenes/pressure/table6_1.toml --csv " + pressure_csv.string());
  ASSERT_EQ(pressure.exit_code, 0) << pressure.output;
  EXPECT_FALSE(has_negative_zero(text_of(pressure_csv)));
  // The validation table's max_penetration_m is -0.0 on every rigid run.
  const std::filesystem::path validation = scratch_path("validation");
  const RunResult validate = run_railjoint("validate --no-figures --out " + validation.string());
  ASSERT_EQ(validate.exit_code, 0) << validate.output;
  EXPECT_FALSE(has_negative_zero(text_of(validation / "validation.csv")));
}

TEST(NegativeZero, JsonReportsWriteZeroUnsigned) {
  // simulate's max_penetration and pressure's rates were -0.0.
  const RunResult simulate = run_railjoint("simulate " + testing_support::default_scene_path() + " --json");
  ASSERT_EQ(simulate.exit_code, 0) << simulate.output;
  EXPECT_FALSE(has_negative_zero(simulate.output));
  const RunResult pressure =
      run_railjoint("pressure " + std::string(RAILJOINT_SOURCE_DIR) + "/scenes/pressure/table6_1.toml --json");
  ASSERT_EQ(pressure.exit_code, 0) << pressure.output;
  EXPECT_FALSE(has_negative_zero(pressure.output));
}

// Issue 40, item 17: the text reports printed values that round to zero with
// their sign: "wheel centre at x = -0.0000 mm" (analytic, 8 validation
// scenes), "sim error -0.0000 %" (simulate, the step-down scenes), "dP/dt =
// -0.0000e+00 MPa/s" (pressure, points 1 and 5). Every number a text report
// shows as zero is unsigned.
TEST(NegativeZero, TextReportsShowZeroUnsigned) {
  const std::string scenes = std::string(RAILJOINT_SOURCE_DIR) + "/scenes/";
  const std::vector<std::string> runs = {
      "analytic " + scenes + "validation/cylinder_config1.toml",
      "simulate " + scenes + "validation/cylinder_config1.toml",
      "simulate " + scenes + "validation/s2_theta30_step_down.toml",
      "simulate " + scenes + "validation/step_down.toml",
      "pressure " + scenes + "pressure/table6_1.toml",
      "pressure " + scenes + "pressure/figure5_3_rectangle.toml",
  };
  for (const std::string& arguments : runs) {
    const RunResult r = run_railjoint(arguments);
    ASSERT_EQ(r.exit_code, 0) << arguments << '\n' << r.output;
    std::string text = r.output;
    for (char& c : text) c = (c == '(' || c == '=') ? ' ' : c;  // "(-0.0000 mm)", "x=-0"
    EXPECT_FALSE(has_negative_zero(text)) << arguments << '\n' << r.output;
  }
}

TEST(NegativeZero, TheTextFilterDropsOnlyTheSignOfAZero) {
  EXPECT_EQ(without_negative_zeros("x = -0.0000 mm, dP/dt = -0.0000e+00 MPa/s | -0 | (-0.000)"),
            "x = 0.0000 mm, dP/dt = 0.0000e+00 MPa/s | 0 | (0.000)");
  // Not zeros, exponents, hyphens, dates and words keep theirs.
  const std::string kept = "-0.0001 -0.5 -1e-05 -10 -05x 1e-00 2026-00-01 step-0 x_-0 --set a=-0.3";
  EXPECT_EQ(without_negative_zeros(kept), kept);
}

}  // namespace
}  // namespace railjoint
