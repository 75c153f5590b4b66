#include "support/atomic_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <stdexcept>
#include <system_error>
#include <utility>

#include <fcntl.h>
#include <unistd.h>

#include "support/input_error.h"
#include "support/no_negative_zero.h"
#include "support/temporary_name.h"

namespace railjoint {

namespace fs = std::filesystem;

namespace {

std::string reason(int error_number) { return error_number != 0 ? std::strerror(error_number) : "write error"; }

// A new, empty file beside `target` that nobody else opens: created with
// O_EXCL (so an existing name, or a link planted there, is never followed)
// and the permissions a plain file would get (0666 less the umask).
fs::path create_temporary_beside(const fs::path& target) {
  const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
  remove_stale_temporaries(folder);  // left by runs killed outright
  for (int attempt = 0; attempt < 1000; ++attempt) {
    const fs::path candidate = folder / temporary_name(target.filename().string(), getpid(), attempt);
    const int fd = ::open(candidate.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) {
      ::close(fd);
      return candidate;
    }
    if (errno != EEXIST) break;
  }
  return {};
}

}  // namespace

void refuse_a_folder_as_file(const fs::path& path, const std::string& option) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw InputError(path.string(), option, "is a folder, not a file to write");
}

AtomicFile::AtomicFile(const fs::path& path, std::string option, int significant_digits)
    : std::ostream(nullptr), path_(path), target_(path), option_(std::move(option)) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);  // follows links
  direct_ = fs::exists(status) && !fs::is_regular_file(status);
  refuse_a_folder_as_file(path, option_);
  if (!direct_) {
    if (fs::is_symlink(fs::symlink_status(path, ec))) target_ = fs::canonical(path, ec);
    if (ec) target_ = path;
    temporary_ = create_temporary_beside(target_);
    if (temporary_.empty()) {
      throw InputError(path.string(), option_,
                       "cannot write this file (does its folder exist?): " + reason(errno));
    }
    removed_if_interrupted_ = RemovedIfInterrupted(temporary_);
  }
  if (!buffer_.open(direct_ ? target_ : temporary_)) {
    const int error_number = buffer_.error();
    if (!temporary_.empty()) fs::remove(temporary_, ec);
    throw InputError(path.string(), option_, "cannot write this file: " + reason(error_number));
  }
  rdbuf(&buffer_);
  precision(significant_digits);
  imbue(without_negative_zero(getloc()));
}

AtomicFile::AtomicFile(AtomicFile&& other) noexcept
    : std::ostream(std::move(other)),
      buffer_(std::move(other.buffer_)),
      path_(std::move(other.path_)),
      target_(std::move(other.target_)),
      temporary_(std::move(other.temporary_)),
      option_(std::move(other.option_)),
      direct_(other.direct_),
      done_(other.done_),
      removed_if_interrupted_(std::move(other.removed_if_interrupted_)) {
  rdbuf(&buffer_);
  other.temporary_.clear();
  other.done_ = true;
}

AtomicFile::~AtomicFile() {
  if (done_) return;
  std::error_code ignored;  // (the buffer closes its file without writing what it holds)
  if (!temporary_.empty()) fs::remove(temporary_, ignored);
}

void AtomicFile::commit() {
  if (done_) return;
  done_ = true;
  // Renamed or removed below, whichever way this ends: ours no longer.
  const RemovedIfInterrupted until_renamed = std::move(removed_if_interrupted_);
  // The buffer keeps the errno of the write that failed (EFBIG, ENOSPC):
  // errno itself may have been changed since by any other call.
  flush();
  const bool written = !fail();
  const bool closed = buffer_.close();
  const int error_number = buffer_.error();
  std::error_code ec;
  if (!written || !closed) {
    if (!temporary_.empty()) fs::remove(temporary_, ec);
    throw std::runtime_error(path_.string() + " (" + option_ + "): cannot write this file: " + reason(error_number) +
                             (direct_ ? "; the output is incomplete" : "; nothing was written there"));
  }
  if (temporary_.empty()) return;
  // Replacing a file keeps its permission bits (a 0600 file stays private),
  // given once it is written: a 0444 file is replaced as `mv -f` would.
  const fs::file_status replaced = fs::status(target_, ec);
  if (fs::is_regular_file(replaced)) fs::permissions(temporary_, replaced.permissions() & fs::perms::all, ec);
  fs::rename(temporary_, target_, ec);
  if (ec) {
    const std::string why = ec.message();
    fs::remove(temporary_, ec);
    throw std::runtime_error(path_.string() + " (" + option_ + "): cannot write this file: " + why);
  }
  temporary_.clear();
}

void finish_standard_output() {
  errno = 0;
  std::cout.flush();
  const bool lost = std::fflush(stdout) != 0 || std::ferror(stdout) != 0 || std::cout.fail();
  if (lost) {
    throw std::runtime_error("standard output: cannot write the report: " + reason(errno));
  }
}

}  // namespace railjoint
