#pragma once
// What a run interrupted by a signal (Ctrl-C, `kill`, a batch system's
// SIGTERM, a closed terminal) leaves behind: nothing of its own. The
// temporary files and staging folders of outputs not yet complete
// (atomic_file.h, staging_folder.h) are hidden names that nothing else
// would ever remove; they are registered here while they exist, and
// remove_on_interrupt() installs handlers for SIGINT, SIGTERM and SIGHUP that
// remove them and then end the process by the same signal (exit status
// 128 + n, as the shell expects). The removal uses system calls only
// (unlink, getdents64, unlinkat, rmdir, nanosleep): a handler may interrupt
// malloc. A signal the parent set to be ignored (nohup) stays ignored.
//
// While outputs are being published (an older render removed, the new files
// renamed into place) a signal is held back until the publication is
// complete (PublishingOutputs), so a folder holds the older output or the
// new one, never a part of each.
//
// The children railjoint runs (support/child_process.h: a figure
// script, ffmpeg) are killed with their groups and waited for before that,
// so nothing they would still write appears after the run ended.

#include <filesystem>

namespace railjoint {

/// Installs the handlers (the railjoint executable does, in main).
void remove_on_interrupt();

/// A path (a file, or a folder holding only files) removed if the process is
/// interrupted while this object holds it: from construction until it is
/// destroyed or forget() is called (the path was published or removed).
/// When all 64 places are taken the path is not held (left, as before).
class RemovedIfInterrupted {
 public:
  RemovedIfInterrupted() = default;
  explicit RemovedIfInterrupted(const std::filesystem::path& path);
  RemovedIfInterrupted(RemovedIfInterrupted&& other) noexcept : slot_(other.slot_) { other.slot_ = -1; }
  RemovedIfInterrupted& operator=(RemovedIfInterrupted&& other) noexcept;
  ~RemovedIfInterrupted() { forget(); }

  void forget();

 private:
  int slot_ = -1;
};

/// While one exists (on any thread), an interrupting signal waits: the last
/// one to go acts on it (removes what is registered, ends the process).
class PublishingOutputs {
 public:
  PublishingOutputs();
  ~PublishingOutputs();
  PublishingOutputs(const PublishingOutputs&) = delete;
  PublishingOutputs& operator=(const PublishingOutputs&) = delete;
};

}  // namespace railjoint
