#include "scenes/cli/figure_script.h"

#include <cstdlib>
#include <stdexcept>

#include <unistd.h>

#include "support/child_process.h"

namespace railjoint {

namespace {

std::string python_interpreter() {
  const char* chosen = std::getenv("RAILJOINT_PYTHON");
  return chosen != nullptr && *chosen != '\0' ? chosen : "/usr/bin/python3";
}

}  // namespace

FigureResult run_figure_script(const std::string& script, const std::vector<std::string>& arguments) {
  const std::filesystem::path path = std::filesystem::path(RAILJOINT_SOURCE_DIR) / "scripts" / "plots" / script;
  const std::string python = python_interpreter();
  if (access(python.c_str(), X_OK) != 0) return {false, "figures skipped: " + python + " not found"};
  if (!run_child(python, {"-c", "import matplotlib"}).succeeded()) {
    return {false, "figures skipped: matplotlib missing (apt-get install python3-matplotlib)"};
  }
  std::vector<std::string> words = {path.string()};
  words.insert(words.end(), arguments.begin(), arguments.end());
  const ChildOutcome outcome = run_child(python, words);
  if (!outcome.succeeded()) {
    throw std::runtime_error("figure script " + script + " failed (" + outcome.how +
                             (outcome.last_error.empty() ? std::string() : "): " + outcome.last_error) +
                             (outcome.last_error.empty() ? ")" : ""));
  }
  return {true, std::string("figures drawn by ").append(script)};
}

}  // namespace railjoint
