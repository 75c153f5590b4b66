#include "scenes/report/figure_script.h"

#include <cstdlib>

namespace railjoint {

namespace {
constexpr const char* kPython = "/usr/bin/python3";

// Single-quoted for /bin/sh, so folder names with spaces survive.
std::string quoted(const std::string& text) {
  std::string out(1, '\'');
  for (char c : text) {
    if (c == '\'') {
      out.append("'\\''");
    } else {
      out.push_back(c);
    }
  }
  out.push_back('\'');
  return out;
}
}  // namespace

FigureResult run_figure_script(const std::string& script, const std::vector<std::string>& arguments) {
  const std::filesystem::path path = std::filesystem::path(RAILJOINT_SOURCE_DIR) / "scripts" / "plots" / script;
  if (!std::filesystem::exists(kPython)) return {false, "figures skipped: /usr/bin/python3 not found"};
  if (std::system((std::string(kPython) + " -c 'import matplotlib' 2>/dev/null").c_str()) != 0) {
    return {false, "figures skipped: matplotlib missing (apt-get install python3-matplotlib)"};
  }
  std::string command = std::string(kPython) + " " + quoted(path.string());
  for (const auto& argument : arguments) command.append(" ").append(quoted(argument));
  if (std::system(command.c_str()) != 0) return {false, std::string("figure script failed: ").append(command)};
  return {true, std::string("figures drawn by ").append(script)};
}

}  // namespace railjoint
