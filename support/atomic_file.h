#pragma once
// Every file a run writes appears whole or not at all. An AtomicFile is
// written under a temporary name in the target's own folder (so the final
// rename is atomic on every local file system) and renamed to its name by
// commit() once all of it reached the disk; a run that fails on the way (a
// full disk, an error in the run, an exception) leaves no truncated file and
// an older file of that name untouched. A path that already exists and is not
// a regular file (a device such as /dev/stdout or /dev/full, a FIFO) is
// written directly, and a write error is still reported. A symbolic link to
// a file stays a link: the file it points to is replaced.
//
// The same for standard output: finish_standard_output() reports a report
// that did not reach its reader.

#include <filesystem>
#include <ostream>
#include <string>

#include "support/checked_file_buffer.h"
#include "support/interrupted_run.h"

namespace railjoint {

class AtomicFile : public std::ostream {
 public:
  /// Opens the temporary file for `path`; `option` is the command-line
  /// option that named it ("--csv"), for messages. Throws InputError naming
  /// the file and the option when it cannot be created (no such folder, no
  /// permission). Numbers are written with `significant_digits`.
  AtomicFile(const std::filesystem::path& path, std::string option, int significant_digits = 10);
  AtomicFile(AtomicFile&& other) noexcept;
  AtomicFile& operator=(AtomicFile&&) = delete;
  /// Removes the temporary file unless commit() ran.
  ~AtomicFile() override;

  /// Flushes and closes the file and gives it its name. Throws
  /// std::runtime_error naming the file (and why: "No space left on
  /// device") when any write failed; the temporary file is removed then.
  void commit();

  const std::filesystem::path& path() const { return path_; }

 private:
  CheckedFileBuffer buffer_;
  std::filesystem::path path_;       ///< as the user gave it
  std::filesystem::path target_;     ///< where the file ends up (a link's target)
  std::filesystem::path temporary_;  ///< empty: written directly (a device, a FIFO), or committed
  std::string option_;
  bool direct_ = false;
  bool done_ = false;
  RemovedIfInterrupted removed_if_interrupted_;  ///< the temporary (interrupted_run.h)
};

/// Throws InputError naming `path` and `option` when a folder has that name
/// (links followed): no file can be written there. AtomicFile checks it
/// first; a staging folder checks every name before it publishes any.
void refuse_a_folder_as_file(const std::filesystem::path& path, const std::string& option);

/// Flushes standard output (std::cout and C's stdout) and throws
/// std::runtime_error when anything written to it was lost (a full disk
/// behind a redirection, a closed pipe).
void finish_standard_output();

}  // namespace railjoint
