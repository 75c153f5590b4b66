#include "scenes/sweeps/sweep_folder_lock.h"

#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include "support/input_error.h"

namespace railjoint {

namespace {

// The holder's pid as its lock file says, or "" (a holder between open and write).
std::string holder_pid(int fd) {
  char text[32] = {};
  const ssize_t got = pread(fd, text, sizeof text - 1, 0);
  if (got <= 0) return "";
  std::string pid(text, static_cast<std::size_t>(got));
  pid.erase(pid.find_last_not_of(" \n") + 1);
  return pid.find_first_not_of("0123456789") == std::string::npos ? pid : "";
}

}  // namespace

SweepFolderLock::SweepFolderLock(const std::filesystem::path& dir, const std::string& lock_name) {
  const std::filesystem::path path = dir / lock_name;
  const std::string folder = dir.string();
  // O_NOFOLLOW and O_NONBLOCK: a link or a FIFO planted under the lock's name
  // fails here or below instead of locking something else or hanging.
  fd_ = open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK, 0644);
  if (fd_ < 0) {
    throw InputError(folder, "--out", "cannot open its lock file " + lock_name + ": " + std::strerror(errno));
  }
  struct stat status {};
  if (fstat(fd_, &status) != 0 || !S_ISREG(status.st_mode)) {
    close(fd_);
    fd_ = -1;
    throw InputError(folder, "--out", "its lock file " + lock_name + " is not a regular file; remove it");
  }
  if (flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int error = errno;
    const std::string pid = holder_pid(fd_);
    close(fd_);
    fd_ = -1;
    if (error == EWOULDBLOCK) {
      throw InputError(folder, "--out",
                       "is in use: another railjoint" + (pid.empty() ? std::string() : " (pid " + pid + ")") +
                           " is writing this sweep's results here; wait for it to end, or use another --out");
    }
    throw InputError(folder, "--out", "cannot lock " + lock_name + ": " + std::strerror(error));
  }
  const std::string pid = std::to_string(getpid()) + "\n";
  if (ftruncate(fd_, 0) != 0 || pwrite(fd_, pid.data(), pid.size(), 0) != static_cast<ssize_t>(pid.size())) {
    // The lock holds without the pid; only the second run's message loses it.
  }
}

SweepFolderLock::~SweepFolderLock() {
  // Closing the descriptor releases the lock; the file stays (removing it
  // would let a third run lock a new file while a second waits on the old).
  if (fd_ >= 0) close(fd_);
}

}  // namespace railjoint
