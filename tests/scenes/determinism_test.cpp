// Determinism: the JSON and CSV outputs of every command are bit-identical
// from one run to the next (nothing depends on the clock, thread timing,
// addresses or uninitialised memory); only the measured wall times differ.
// scripts/sanitize_test.sh compares the release and sanitizer builds' outputs
// the same way.

#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/file_text.h"
#include "tests/support/run_cli.h"
#include "tests/support/scratch_dir.h"

namespace railjoint {
namespace {

namespace fs = std::filesystem;
using testing_support::default_scene_path;
using testing_support::RunResult;
using testing_support::scratch_path;

std::string read(const std::filesystem::path& path) { return testing_support::file_text(path); }

// The JSON with every "wall_time_s" removed (a measured time, not a result).
std::string without_wall_times(const std::string& text) {
  nlohmann::json j = nlohmann::json::parse(text);
  const auto strip = [](auto& self, nlohmann::json& node) -> void {
    if (node.is_object()) {
      node.erase("wall_time_s");
      for (auto& [key, value] : node.items()) self(self, value);
    } else if (node.is_array()) {
      for (auto& value : node) self(self, value);
    }
  };
  strip(strip, j);
  return j.dump(2);
}

struct Outputs {
  std::string json;
  std::string csv;
};

Outputs run_once(const std::string& command, const std::string& name) {
  const fs::path csv = scratch_path(name + ".csv");
  // stdout only: the JSON (the subshell keeps stderr out of the captured output).
  std::string line("(");  // appended: GCC 12 warns falsely (-Wrestrict) on "(" + string
  line += std::string(RAILJOINT_EXE) + " " + command + " --json --csv " + csv.string() + " 2>/dev/null)";
  const RunResult r = testing_support::run_shell(line);
  EXPECT_EQ(r.exit_code, 0) << command << "\n" << r.output;
  return {without_wall_times(r.output), read(csv)};
}

TEST(Determinism, JsonAndCsvAreBitIdenticalAcrossRuns) {
  const std::string source = RAILJOINT_SOURCE_DIR;
  const std::vector<std::pair<std::string, std::string>> commands = {
      {"analytic", "analytic " + default_scene_path()},
      {"simulate", "simulate " + default_scene_path()},
      {"simulate_step_down", "simulate " + source + "/scenes/validation/step_down.toml"},
      {"simulate_inertial", "simulate " + default_scene_path() + " --set sim.mode=inertial --set sim.run_out_time=0.002"},
      {"pressure", "pressure " + source + "/scenes/pressure/table6_1.toml --set contact_patch.steps=200"},
  };
  for (const auto& [name, command] : commands) {
    const Outputs first = run_once(command, name + "_1");
    const Outputs second = run_once(command, name + "_2");
    std::cout << name << ": JSON " << first.json.size() << " bytes, CSV " << first.csv.size() << " bytes\n";
    EXPECT_GT(first.json.size(), 100u) << name;
    EXPECT_GT(first.csv.size(), 100u) << name;
    EXPECT_EQ(first.json, second.json) << name;
    EXPECT_EQ(first.csv, second.csv) << name;
  }
}

}  // namespace
}  // namespace railjoint
