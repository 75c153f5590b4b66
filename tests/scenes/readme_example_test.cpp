// Issue 29, item 10: the README's first screen is the start, and its example
// is the program's real output. The example under "## Start here" is run as
// printed (from the source folder) and must print exactly the lines the
// README shows; the section must begin within the first 40 lines.

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/run_cli.h"

namespace railjoint {
namespace {

std::vector<std::string> readme_lines() {
  std::ifstream in(std::string(RAILJOINT_SOURCE_DIR) + "/README.md");
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

TEST(ReadmeExample, TheFirstScreenShowsTheRealOutputOfItsExample) {
  const std::vector<std::string> lines = readme_lines();
  std::size_t start = lines.size();
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (lines[i] == "## Start here") start = i;
  }
  ASSERT_LT(start, 40u) << "\"## Start here\" is not on the first screen";
  const std::string prompt = "$ build/scenes/railjoint ";
  std::size_t command_line = lines.size();
  for (std::size_t i = start; i < lines.size(); ++i) {
    if (lines[i].rfind(prompt, 0) == 0) {
      command_line = i;
      break;
    }
  }
  ASSERT_LT(command_line, lines.size()) << "no example command under ## Start here";
  std::string shown;
  for (std::size_t i = command_line + 1; i < lines.size() && lines[i].rfind("$ ", 0) != 0 && lines[i] != "```"; ++i) {
    shown += lines[i] + "\n";
  }
  ASSERT_FALSE(shown.empty()) << lines[command_line];
  const std::string arguments = lines[command_line].substr(prompt.size());
  const testing_support::RunResult r =
      testing_support::run_shell("cd " + std::string(RAILJOINT_SOURCE_DIR) + " && " + RAILJOINT_EXE + " " + arguments);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output, shown) << "README.md's example is not what `railjoint " << arguments << "` prints";
}

}  // namespace
}  // namespace railjoint
