#include "scenes/input_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>

#include "scenes/toml_limits.h"
#include "support/input_error.h"

namespace railjoint {

namespace {

std::string too_large(std::size_t bytes, const std::string& kind) {
  return "is " + std::to_string(bytes) + " bytes or more; a " + kind + " file is a few kB at most (the limit is " +
         std::to_string(kMaxSceneBytes) + ")";
}

}  // namespace

std::string read_input_file(const std::string& path, const std::string& kind) {
  // Checked here, not by the CLI parser: one line and exit code 2 like every other input error.
  std::error_code error;
  if (!std::filesystem::exists(path, error)) throw InputError(path, "", "no such " + kind + " file");
  if (!std::filesystem::is_regular_file(path, error)) {
    throw InputError(path, "", "is not a file (a " + kind + " is a .toml file)");
  }
  // Before reading it: an input is small, a mistyped path may name a huge file.
  if (const auto bytes = std::filesystem::file_size(path, error); !error && bytes > kMaxSceneBytes) {
    throw InputError(path, "", too_large(bytes, kind));
  }
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> in(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!in) throw InputError(path, "", "cannot open " + kind + " file: " + std::strerror(errno));
  // Read with every error checked: a file the system calls regular may still
  // fail to read (/proc/self/mem reports size 0 and gives EIO), and the empty
  // text a failed read leaves would be a scene of all defaults. The size
  // reported above is not trusted either (files in /proc report 0 bytes),
  // so at most one byte past the limit is read.
  std::string text(kMaxSceneBytes + 1, '\0');
  std::size_t read_bytes = 0;
  while (read_bytes < text.size()) {
    const std::size_t got = std::fread(text.data() + read_bytes, 1, text.size() - read_bytes, in.get());
    read_bytes += got;
    if (got == 0) break;
  }
  if (std::ferror(in.get())) {
    throw InputError(path, "", "cannot read " + kind + " file: " + std::strerror(errno));
  }
  if (read_bytes > kMaxSceneBytes) throw InputError(path, "", too_large(read_bytes, kind));
  text.resize(read_bytes);
  return text;
}

}  // namespace railjoint
