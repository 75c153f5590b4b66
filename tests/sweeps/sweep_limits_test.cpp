// Sizes a sweep (or a pressure run) accepts are sizes it can run (issue 30):
// a grid or sample larger than the bound, a polygon run past its work budget,
// are refused by key; a --jobs the system cannot start is a message, not an
// abort; ranges near the largest double stay finite; a long list of numbers
// on one line is read.

#include <cmath>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "models/input_error.h"
#include "scenes/scene_file.h"
#include "scenes/sweeps/case_grid.h"
#include "scenes/sweeps/case_models.h"
#include "scenes/sweeps/sweep_file.h"
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


}  // namespace
}  // namespace railjoint
