// libFuzzer target: any bytes as a scene file (tests/fuzz/scene_checks.h says
// what is checked). Seeds: every .toml file of scenes/.

#include <cstddef>
#include <cstdint>
#include <string>

#include "tests/fuzz/scene_checks.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  railjoint::fuzz::check_scene(std::string(reinterpret_cast<const char*>(data), size), {});
  return 0;
}
