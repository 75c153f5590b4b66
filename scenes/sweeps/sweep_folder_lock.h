#pragma once
// One writer per results file of a sweep folder. Two runs appending to one
// results.csv splice rows mid-line, and a resume started while a killed
// mpirun's rank 0 still writes reads a file that is still growing; so the
// process that writes holds an advisory lock (flock(2)) on a lock file in the
// folder for the whole run, with its pid in it for the message a second run
// prints. The kernel drops the lock when the process ends, however it ends
// (kill -9 too): a stale lock file never blocks a resume.

#include <filesystem>
#include <string>

namespace railjoint {

class SweepFolderLock {
 public:
  /// Takes the lock `lock_name` in `dir` (created if need be), without
  /// waiting. Throws InputError naming the folder, --out and the holder's pid
  /// when another process holds it, or when the lock file is not a regular
  /// file (a FIFO, a link to a device).
  SweepFolderLock(const std::filesystem::path& dir, const std::string& lock_name);
  ~SweepFolderLock();
  SweepFolderLock(const SweepFolderLock&) = delete;
  SweepFolderLock& operator=(const SweepFolderLock&) = delete;

 private:
  int fd_ = -1;
};

}  // namespace railjoint
