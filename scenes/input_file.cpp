#include "scenes/input_file.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "models/input_error.h"

namespace railjoint {

std::string read_input_file(const std::string& path, const std::string& kind) {
  // Checked here, not by the CLI parser: one line and exit code 2 like every other input error.
  std::error_code error;
  if (!std::filesystem::exists(path, error)) throw InputError(path, "", "no such " + kind + " file");
  if (!std::filesystem::is_regular_file(path, error)) {
    throw InputError(path, "", "is not a file (a " + kind + " is a .toml file)");
  }
  std::ifstream in(path);
  if (!in) throw InputError(path, "", "cannot open " + kind + " file (permissions?)");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace railjoint
