#pragma once
// A file's bytes as a string, for tests that compare what a command wrote.

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace railjoint::testing_support {

/// The whole file, byte for byte ("" when it cannot be read).
inline std::string file_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace railjoint::testing_support
