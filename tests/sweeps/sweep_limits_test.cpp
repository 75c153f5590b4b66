// Sizes a sweep (or a pressure run) accepts are sizes it can run (issue 30):
// a grid or sample larger than the bound, a polygon run past its work budget,
// are refused by key; a --jobs the system cannot start is a message, not an
// abort; ranges near the largest double stay finite; a long list of numbers
// on one line is read.

#include <cmath>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "scenes/scene_file.h"
#include "scenes/sweeps/case_grid.h"
#include "scenes/sweeps/case_models.h"
#include "scenes/sweeps/sweep_file.h"
#include "support/input_error.h"
#include "tests/support/run_cli.h"
#include "tests/sweeps/sweep_test_support.h"

namespace railjoint {
namespace {

namespace fs = std::filesystem;
using testing_support::RunResult;
using testing_support::run_shell;
using testing_support::temporary_folder;
using testing_support::write_sweep;

SweepFile parsed(const std::string& text) {
  const fs::path dir = temporary_folder("sweep_limits_parse");
  return load_sweep_file(write_sweep(dir, "s.toml", text), case_model_names());
}

// The InputError's key and text loading `text` throws ("" when it loads).
std::string refusal(const std::string& text) {
  try {
    parsed(text);
  } catch (const InputError& error) {
    std::cout << error.what() << "\n";
    return error.key() + ": " + error.message();
  }
  return "";
}

// count = 1e8 took 8.8 GB before its first row; 1e9 (grid or sample) ended
// in std::bad_alloc naming no key.
TEST(SweepLimits, ASweepLargerThanTheBoundIsRefusedByKey) {
  const std::string grid = refusal("run = [\"analytic\"]\n[axes]\n\"wheel.y\" = { from = 0.0, to = 0.019, count = 100000000 }\n");
  EXPECT_EQ(grid.rfind("axes.wheel.y.count: must be an integer in [1, 10000000], got 100000000: a sweep holds at most", 0), 0u)
      << grid;
  const std::string product = refusal(
      "run = [\"analytic\"]\n[axes]\n\"wheel.y\" = { from = 0.0, to = 0.019, count = 10000 }\n"
      "\"joint.theta_deg\" = { from = 15.0, to = 90.0, count = 10000 }\n");
  EXPECT_EQ(product.rfind("axes: the grid has more than 10000000 cases", 0), 0u) << product;
  const std::string sample = refusal(
      "run = [\"analytic\"]\n[axes]\n\"wheel.y\" = { from = 0.0, to = 0.019 }\n[sample]\ncount = 1000000000\n");
  EXPECT_EQ(sample.rfind("sample.count: must be an integer in [1, 10000000], got 1000000000", 0), 0u) << sample;
  // A sample within the case bound but with many sampled ranges holds too many coordinates.
  std::string wide = "run = [\"analytic\"]\n[axes]\n";
  for (const char* key : {"wheel.y", "wheel.speed", "joint.beta", "joint.theta_deg", "wheel.radius", "wheel.mass"}) {
    wide += std::string("\"") + key + "\" = { from = 0.001, to = 0.01 }\n";
  }
  wide += "[sample]\ncount = 10000000\n";
  const std::string coordinates = refusal(wide);
  EXPECT_EQ(coordinates.rfind("sample.count: must be <= 8333333 with 6 sampled ranges", 0), 0u) << coordinates;
}

// contact_patch.vertices = 1e6 and steps = 1e7, both in range, was a run of
// some 18 days.
TEST(SweepLimits, APolygonPressureRunPastItsWorkBudgetIsRefusedByKey) {
  const std::string patch = "[joint]\ngap = 0.006\n[contact_patch]\nshape = \"polygon\"\nvertices = 1000000\n";
  try {
    parse_scene(patch + "steps = 10000000\n", "p.toml");
    ADD_FAILURE() << "a 1e13 vertex-step run was accepted";
  } catch (const InputError& error) {
    std::cout << error.what() << "\n";
    EXPECT_EQ(error.key(), "contact_patch.steps");
    EXPECT_NE(error.message().find("must be <= 1000"), std::string::npos) << error.message();
  }
  // 1e6 x 1000 steps (the default) is the budget itself, some 3 minutes.
  EXPECT_NO_THROW(parse_scene(patch, "p.toml"));
  EXPECT_THROW(parse_scene(patch + "steps = 1001\n", "p.toml"), InputError);
}

// A --jobs the system cannot start (here under a 2 GB address-space limit, 8
// MB stacks) aborted with "terminate called without an active exception".
TEST(SweepLimits, JobsTheSystemCannotStartAreAMessageNotAnAbort) {
#if defined(__SANITIZE_ADDRESS__)
  // AddressSanitizer reserves terabytes of shadow address space at start-up:
  // under `ulimit -v` the sanitizer build's executable cannot start at all.
  GTEST_SKIP() << "ulimit -v stops an AddressSanitizer build before main";
#endif
  const fs::path dir = temporary_folder("sweep_limits_jobs");
  const std::string sweep =
      write_sweep(dir, "s.toml", "run = [\"analytic\"]\n[axes]\n\"wheel.y\" = { from = 0.0, to = 0.019, count = 20000 }\n");
  const std::string limits = "ulimit -s 8192; ulimit -v 2000000; ";
  for (const std::string& command :
       {"sweep " + sweep + " --out " + (dir / "out").string() + " --jobs 500", "validate --out " + (dir / "validation").string() + " --jobs 600"}) {
    const RunResult r = run_shell("(" + limits + RAILJOINT_EXE + " " + command + ") 2>&1");
    std::cout << r.output;
    EXPECT_EQ(r.exit_code, 1) << command;
    EXPECT_EQ(r.output.find("terminate called"), std::string::npos) << command;
    const std::string jobs = command.substr(command.rfind("--jobs"));
    EXPECT_NE(r.output.find("railjoint: error: " + jobs + ": the system refused to start thread "), std::string::npos)
        << command;
  }
}

// -1e308..1e308 gave inf as its middle value, a log range 1e-200..1e200 inf
// where it should give 1.
TEST(SweepLimits, RangesNearTheLargestDoubleStayFinite) {
  const SweepFile sweep = parsed(
      "run = [\"analytic\"]\n[axes]\n\"wheel.speed\" = { from = -1e308, to = 1e308, count = 3 }\n"
      "\"joint.beta\" = { from = 1e-200, to = 1e200, count = 3, scale = \"log\" }\n");
  const double middle = std::get<double>(sweep.axes[0].values[1]);
  const double log_middle = std::get<double>(sweep.axes[1].values[1]);
  std::cout << "even middle " << middle << ", log middle " << log_middle << "\n";
  EXPECT_EQ(middle, 0.0);
  EXPECT_NEAR(log_middle, 1.0, 1e-12);  // exp(0) up to the rounding of the two logarithms
  // Sampled ranges as well: every point inside its range.
  const SweepFile sampled = parsed(
      "run = [\"analytic\"]\n[axes]\n\"wheel.speed\" = { from = -1e308, to = 1e308 }\n"
      "\"joint.beta\" = { from = 1e-200, to = 1e200, scale = \"log\" }\n[sample]\ncount = 50\n");
  const CaseGrid grid(sampled);
  std::vector<SceneOverride> values;
  for (std::uint64_t i = 0; i < grid.size(); ++i) {
    grid.overrides(i, values);
    for (const SceneOverride& o : values) {
      const double v = std::get<double>(o.value);
      EXPECT_TRUE(std::isfinite(v) && v != 0.0) << o.section << "." << o.key << " = " << v;
    }
  }
  // An ordinary range keeps its exact values: 0.019 * 5 / 38 is 0.0025.
  const SweepFile plain = parsed("run = [\"analytic\"]\n[axes]\n\"wheel.y\" = { from = 0.0, to = 0.019, count = 39 }\n");
  EXPECT_EQ(std::get<double>(plain.axes[0].values[5]), 0.0025);
}

// 1200 numbers on one line were refused as nesting too deep (their decimal
// points counted as dotted keys).
TEST(SweepLimits, ALongListOfNumbersOnOneLineIsRead) {
  std::string list;
  for (int i = 0; i < 1200; ++i) {
    if (i > 0) list += ", ";
    list += std::to_string(i * 1e-5);
  }
  const std::string text = "run = [\"analytic\"]\n[axes]\n\"wheel.y\" = [" + list + "]\n";
  EXPECT_EQ(refusal(text), "");
  EXPECT_EQ(parsed(text).axes[0].values.size(), 1200u);
  // A key of 1001 dots still nests too deep.
  std::string deep = "a";
  for (int i = 0; i < 1001; ++i) deep += ".a";
  EXPECT_NE(refusal("run = [\"analytic\"]\n" + deep + " = 1\n").find("holds more than 1000 dots"), std::string::npos);
}

}  // namespace
}  // namespace railjoint
