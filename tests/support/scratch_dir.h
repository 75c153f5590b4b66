#pragma once
// A folder of its own for every test, so that two test runs at once (two
// `ctest` processes, or ctest -j) never write the same file: made with
// mkdtemp under $TMPDIR (else /tmp), named after the test so a failed run's
// files are easy to find. Removed when the test passes (or is skipped), kept
// when it fails.
// No test writes a fixed name in the temporary folder (checked by
// tests/support/scratch_dir_test.cpp).

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include <gtest/gtest.h>

namespace railjoint::testing_support {

namespace scratch_detail {

// The folders made for the running test, removed when it ends if it passed.
// Each test binary runs one test per process under ctest, but a direct run
// of the binary runs them all: the folder belongs to the test, not the process.
class Registry : public ::testing::EmptyTestEventListener {
 public:
  static Registry& get() {
    // Owned by gtest's listener list once appended (it deletes it at exit).
    static Registry* registry = [] {
      auto* r = new Registry;
      ::testing::UnitTest::GetInstance()->listeners().Append(r);
      return r;
    }();
    return *registry;
  }

  std::filesystem::path folder_for_current_test() {
    const std::string test = current_test_name();
    auto found = folders_.find(test);
    if (found != folders_.end()) return found->second;
    const char* tmpdir = std::getenv("TMPDIR");
    const std::filesystem::path base = tmpdir != nullptr && *tmpdir != '\0' ? tmpdir : "/tmp";
    std::string pattern = (base / ("railjoint_" + test + "_XXXXXX")).string();
    if (mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp failed for " + pattern);
    return folders_.emplace(test, pattern).first->second;
  }

  void OnTestEnd(const ::testing::TestInfo& info) override {
    const std::string test = name_of(info);
    auto found = folders_.find(test);
    if (found == folders_.end()) return;
    if (!info.result()->Failed()) {  // passed or skipped
      std::error_code ignored;
      std::filesystem::remove_all(found->second, ignored);
    } else {
      std::printf("scratch folder kept for the failed test: %s\n", found->second.c_str());
    }
    folders_.erase(found);
  }

 private:
  static std::string name_of(const ::testing::TestInfo& info) {
    std::string name = std::string(info.test_suite_name()) + "." + info.name();
    // Parameterised tests have '/' in their names.
    for (char& c : name) {
      if (c == '/' || c == ' ') c = '_';
    }
    return name;
  }
  static std::string current_test_name() {
    const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
    return info == nullptr ? std::string("outside_a_test") : name_of(*info);
  }

  std::map<std::string, std::filesystem::path> folders_;
};

}  // namespace scratch_detail

/// The calling test's own folder (created on the first call, the same folder
/// for every later call in that test).
inline std::filesystem::path scratch_dir() { return scratch_detail::Registry::get().folder_for_current_test(); }

/// A path named `name` inside the calling test's own folder; nothing is
/// created there (a test may need a folder the program has to create).
inline std::filesystem::path scratch_path(const std::string& name) { return scratch_dir() / name; }

}  // namespace railjoint::testing_support
