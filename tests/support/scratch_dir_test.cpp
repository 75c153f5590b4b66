// Every test writes under a folder of its own (tests/support/scratch_dir.h),
// so two test runs at once never overwrite each other's files.

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/scratch_dir.h"

namespace railjoint {
namespace {

namespace fs = std::filesystem;
using testing_support::scratch_dir;
using testing_support::scratch_path;

fs::path remembered_from_first_test;

TEST(ScratchDir, IsAFreshFolderNamedAfterTheTest) {
  const fs::path dir = scratch_dir();
  std::cout << "scratch folder: " << dir << "\n";
  ASSERT_TRUE(fs::is_directory(dir));
  EXPECT_TRUE(fs::is_empty(dir));
  EXPECT_NE(dir.filename().string().find("ScratchDir.IsAFreshFolderNamedAfterTheTest_"), std::string::npos);
  EXPECT_EQ(scratch_dir(), dir) << "one folder per test";
  EXPECT_EQ(scratch_path("a.csv"), dir / "a.csv");
  EXPECT_FALSE(fs::exists(scratch_path("a.csv"))) << "scratch_path creates nothing";
  std::ofstream(dir / "left.txt") << "removed with the folder when the test passes";
  remembered_from_first_test = dir;
}

TEST(ScratchDir, ThePreviousTestsFolderIsGoneAndThisOneDiffers) {
  // Under ctest each test runs in a process of its own; run directly, the
  // binary runs both in order and the first one's folder went when it passed.
  if (!remembered_from_first_test.empty()) {
    EXPECT_FALSE(fs::exists(remembered_from_first_test)) << remembered_from_first_test;
    EXPECT_NE(scratch_dir(), remembered_from_first_test);
  }
  const char* tmpdir = std::getenv("TMPDIR");
  const fs::path base = tmpdir != nullptr && *tmpdir != '\0' ? fs::path(tmpdir) : fs::path("/tmp");
  EXPECT_EQ(scratch_dir().parent_path(), base);
}

// No test writes a fixed name into the shared temporary folder: gtest's
// TempDir() and std::filesystem::temp_directory_path() are the same folder
// for every process, so two runs at once overwrote each other's files there.
TEST(ScratchDir, NoTestUsesASharedTemporaryName) {
  const char* const shared[] = {"TempDir()", "temp_directory_path()", "\"/tmp/"};
  std::vector<std::string> offenders;
  int files = 0;
  for (const auto& entry : fs::recursive_directory_iterator(fs::path(RAILJOINT_SOURCE_DIR) / "tests")) {
    const fs::path& path = entry.path();
    if (!entry.is_regular_file() || (path.extension() != ".cpp" && path.extension() != ".h")) continue;
    if (path.filename() == "scratch_dir.h" || path.filename() == "scratch_dir_test.cpp") continue;
    ++files;
    std::ifstream in(path);
    int line_number = 0;
    for (std::string line; std::getline(in, line);) {
      ++line_number;
      if (line.find("XXXXXX") != std::string::npos) continue;  // a mkdtemp template: unique by construction
      for (const char* name : shared) {
        if (line.find(name) != std::string::npos) offenders.push_back(path.string() + ":" + std::to_string(line_number));
      }
    }
  }
  std::cout << files << " test sources scanned, " << offenders.size() << " with a shared temporary name\n";
  for (const std::string& o : offenders) std::cout << "  " << o << "\n";
  EXPECT_GT(files, 20);
  EXPECT_TRUE(offenders.empty());
}

}  // namespace
}  // namespace railjoint
