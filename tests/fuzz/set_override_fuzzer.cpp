// libFuzzer target: any bytes as --set overrides, one per line, on the
// default scene (tests/fuzz/scene_checks.h says what is checked). Seeds:
// every key = value of scenes/*.toml as section.key=value lines.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "tests/fuzz/scene_checks.h"

namespace {

// scenes/default.toml's keys, without its comments.
const char* const kDefaultScene = R"(name = "default"
[joint]
kind = "inclined"
theta_deg = 30.0
beta = 0.03
half_width = 0.020
[wheel]
radius = 0.475
mass = 750.0
width = 0.0
y = 0.015
speed = 50.0
)";

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::vector<std::string> overrides;
  std::string line;
  for (std::size_t i = 0; i <= size; ++i) {
    if (i == size || data[i] == '\n') {
      if (!line.empty()) overrides.push_back(line);
      line.clear();
    } else {
      line += static_cast<char>(data[i]);
    }
  }
  railjoint::fuzz::check_scene(kDefaultScene, overrides);
  return 0;
}
