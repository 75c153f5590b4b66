#include "scenes/input_file.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "models/input_error.h"
#include "scenes/toml_limits.h"

namespace railjoint {

std::string read_input_file(const std::string& path, const std::string& kind) {
  // Checked here, not by the CLI parser: one line and exit code 2 like every other input error.
  std::error_code error;
  if (!std::filesystem::exists(path, error)) throw InputError(path, "", "no such " + kind + " file");
  if (!std::filesystem::is_regular_file(path, error)) {
    throw InputError(path, "", "is not a file (a " + kind + " is a .toml file)");
  }
  // Before reading it: an input is small, a mistyped path may name a huge file.
  if (const auto bytes = std::filesystem::file_size(path, error); !error && bytes > kMaxSceneBytes) {
    throw InputError(path, "",
                     "is " + std::to_string(bytes) + " bytes; a " + kind + " file is a few kB at most (the limit is " +
                         std::to_string(kMaxSceneBytes) + ")");
  }
  std::ifstream in(path);
  if (!in) throw InputError(path, "", "cannot open " + kind + " file (permissions?)");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace railjoint
