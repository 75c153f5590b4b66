#include "scenes/report/interrupted_run.h"

#include <array>
#include <atomic>
#include <csignal>
#include <cstring>
#include <string>
#include <system_error>

#include <fcntl.h>
#include <sys/syscall.h>
#include <unistd.h>

namespace railjoint {

namespace {

// A run holds a handful at once: a render's staging folder and the files
// its report writes, a sweep's results, a study's tables.
constexpr int kSlots = 64;
constexpr std::size_t kMaxPath = 4096;

enum SlotState : int { kFree, kFilling, kHeld };

struct Slot {
  std::atomic<int> state{kFree};
  char path[kMaxPath];
};

std::array<Slot, kSlots> slots;

// A folder's entries by getdents64 (no malloc), each unlinked; then the
// folder itself. Its entries are files: a staging folder holds no folders.
void remove_folder(const char* path) {
  const int fd = static_cast<int>(syscall(SYS_open, path, O_RDONLY | O_DIRECTORY | O_CLOEXEC));
  if (fd < 0) return;
  alignas(8) char buffer[8192];
  for (;;) {
    const long n = syscall(SYS_getdents64, fd, buffer, sizeof buffer);
    if (n <= 0) break;
    for (long at = 0; at < n;) {
      // struct linux_dirent64: inode (8), offset (8), record length (2), type (1), name.
      unsigned short record = 0;
      std::memcpy(&record, buffer + at + 16, sizeof record);
      const char* name = buffer + at + 19;
      if (std::strcmp(name, ".") != 0 && std::strcmp(name, "..") != 0) unlinkat(fd, name, 0);
      at += record;
    }
  }
  close(fd);
  rmdir(path);
}

void on_interrupt(int signal_number) {
  for (Slot& slot : slots) {
    if (slot.state.load() != kHeld) continue;
    if (unlink(slot.path) != 0) remove_folder(slot.path);
  }
  std::signal(signal_number, SIG_DFL);
  std::raise(signal_number);
}

}  // namespace

void remove_on_interrupt() {
  for (const int signal_number : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction action {};
    action.sa_handler = on_interrupt;
    sigemptyset(&action.sa_mask);
    sigaction(signal_number, &action, nullptr);
  }
}

int remove_if_interrupted(const std::filesystem::path& path) {
  std::error_code ec;
  const std::filesystem::path absolute = std::filesystem::absolute(path, ec);
  const std::string& text = ec ? path.native() : absolute.native();
  if (text.size() >= kMaxPath) return -1;
  for (int i = 0; i < kSlots; ++i) {
    int expected = kFree;
    if (!slots[i].state.compare_exchange_strong(expected, kFilling)) continue;
    std::memcpy(slots[i].path, text.c_str(), text.size() + 1);
    slots[i].state.store(kHeld);
    return i;
  }
  return -1;
}

void forget_on_interrupt(int slot) {
  if (slot >= 0 && slot < kSlots) slots[static_cast<std::size_t>(slot)].state.store(kFree);
}

}  // namespace railjoint
