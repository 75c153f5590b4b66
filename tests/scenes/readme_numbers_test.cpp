// Issue 40, item 16: numbers the README (and now the manual, docs/) quotes had gone stale ("17
// validation scenes" against the 16 that `validate` runs, a design-map error
// and suspect count from an older simulation). Where a quoted number is an
// output a test can run in a moment, it is compared with that output.

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/run_cli.h"

namespace railjoint {
namespace {

const std::string kSource = RAILJOINT_SOURCE_DIR;

// The README and the manual (docs/*.md) as one line: a quote may wrap anywhere.
std::string readme_text() {
  std::vector<std::filesystem::path> files = {kSource + "/README.md"};
  for (const auto& entry : std::filesystem::directory_iterator(kSource + "/docs")) {
    if (entry.path().extension() == ".md") files.push_back(entry.path());
  }
  std::string text, line;
  for (const std::filesystem::path& file : files) {
    std::ifstream in(file);
    while (std::getline(in, line)) text += line + ' ';
  }
  return text;
}

// "N validation scenes" and "`railjoint validate` (N scenes" name the scenes validate runs.
TEST(ReadmeNumbers, TheValidationSceneCountIsTheScenesValidateRuns) {
  std::size_t scenes = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kSource + "/scenes/validation")) {
    scenes += entry.path().extension() == ".toml" ? 1 : 0;
  }
  const std::string text = readme_text();
  // (Not std::regex: GCC 12 warns falsely in <regex> under the sanitizer build.)
  int quotes = 0;
  const auto check = [&](std::size_t digits_end, const std::string& what) {
    std::size_t begin = digits_end;
    while (begin > 0 && std::isdigit(static_cast<unsigned char>(text[begin - 1])) != 0) --begin;
    if (begin == digits_end) return;
    std::cout << "README: \"" << text.substr(begin, digits_end - begin) << what << "\"; scenes/validation holds "
              << scenes << '\n';
    EXPECT_EQ(std::stoul(text.substr(begin, digits_end - begin)), scenes) << what;
    ++quotes;
  };
  for (std::size_t at = text.find(" validation scenes"); at != std::string::npos;
       at = text.find(" validation scenes", at + 1)) {
    check(at, " validation scenes");
  }
  const std::string validate = "`railjoint validate` (";
  for (std::size_t at = text.find(validate); at != std::string::npos; at = text.find(validate, at + 1)) {
    std::size_t end = at + validate.size();
    while (end < text.size() && std::isdigit(static_cast<unsigned char>(text[end])) != 0) ++end;
    if (text.compare(end, 7, " scenes") == 0) check(end, " scenes (validate)");
  }
  EXPECT_GE(quotes, 2);
}

// The real-geometry example: "1275.045 N s, 1.13x the square joint's".
TEST(ReadmeNumbers, TheConeExamplesJumpIsWhatAnalyticPrints) {
  const testing_support::RunResult r =
      testing_support::run_railjoint("analytic " + kSource + "/scenes/geometry/60e1_cone.toml --json");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json report = nlohmann::json::parse(r.output);
  char quote[96];
  std::snprintf(quote, sizeof quote, "%.3f N s, %.2fx the square joint's", report.at("exact_Ns").get<double>(),
                report.at("relative_to_square_joint").get<double>());
  std::cout << "analytic: " << quote << '\n';
  EXPECT_NE(readme_text().find(quote), std::string::npos) << "the README does not quote \"" << quote << "\"";
}

}  // namespace
}  // namespace railjoint
