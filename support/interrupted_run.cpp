#include "support/interrupted_run.h"

#include <array>
#include <cerrno>
#include <atomic>
#include <csignal>
#include <cstring>
#include <ctime>
#include <string>
#include <system_error>

#include <fcntl.h>
#include <sys/syscall.h>
#include <unistd.h>

#include "support/child_process.h"

namespace railjoint {

namespace {

// A run holds a handful at once: a render's staging folder and the files
// its report writes, a sweep's results, a study's tables.
constexpr int kSlots = 64;
constexpr std::size_t kMaxPath = 4096;

// kFilling: a path being copied in; kRemoving: the handler is reading it
// (RemovedIfInterrupted::forget then waits, so the slot is not refilled under it).
enum SlotState : int { kFree, kFilling, kHeld, kRemoving };

struct Slot {
  std::atomic<int> state{kFree};
  char path[kMaxPath];
};

std::array<Slot, kSlots> slots;

std::atomic<int> publishing{0};        // PublishingOutputs alive
std::atomic<int> deferred_signal{0};   // a signal that came while publishing

void pause_briefly() {
  const timespec millisecond{0, 1000000};
  nanosleep(&millisecond, nullptr);
}

// A folder's entries by getdents64 (no malloc), each unlinked; then the
// folder itself. Its entries are files: a staging folder holds no folders.
// Other threads may still be writing frames into it: repeated until the
// folder is gone (their next open then fails), for at most ~0.2 s.
void remove_folder(const char* path) {
  for (int attempt = 0; attempt < 200; ++attempt) {
    const int fd = open(path, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
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
    if (rmdir(path) == 0) return;
    pause_briefly();
  }
}

void remove_registered_and_end(int signal_number) {
  kill_children_of_interrupted_run();  // first: nothing it writes appears after the removal
  for (Slot& slot : slots) {
    int held = kHeld;
    if (!slot.state.compare_exchange_strong(held, kRemoving)) continue;
    if (unlink(slot.path) != 0) remove_folder(slot.path);
  }
  std::signal(signal_number, SIG_DFL);
  std::raise(signal_number);  // delivered when the handler returns: the process ends
}

void on_interrupt(int signal_number) {
  if (publishing.load() > 0) {
    int none = 0;
    deferred_signal.compare_exchange_strong(none, signal_number);
    return;
  }
  remove_registered_and_end(signal_number);
}

}  // namespace

void remove_on_interrupt() {
  for (const int signal_number : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction previous {};
    if (sigaction(signal_number, nullptr, &previous) == 0 && previous.sa_handler == SIG_IGN) continue;  // nohup
    struct sigaction action {};
    action.sa_handler = on_interrupt;
    sigemptyset(&action.sa_mask);
    sigaction(signal_number, &action, nullptr);
  }
}

RemovedIfInterrupted::RemovedIfInterrupted(const std::filesystem::path& path) {
  std::error_code ec;
  const std::filesystem::path absolute = std::filesystem::absolute(path, ec);
  const std::string& text = ec ? path.native() : absolute.native();
  if (text.size() >= kMaxPath) return;
  for (int i = 0; i < kSlots; ++i) {
    int expected = kFree;
    if (!slots[i].state.compare_exchange_strong(expected, kFilling)) continue;
    std::memcpy(slots[i].path, text.c_str(), text.size() + 1);
    slots[i].state.store(kHeld);
    slot_ = i;
    return;
  }
}

RemovedIfInterrupted& RemovedIfInterrupted::operator=(RemovedIfInterrupted&& other) noexcept {
  if (this != &other) {
    forget();
    slot_ = other.slot_;
    other.slot_ = -1;
  }
  return *this;
}

void RemovedIfInterrupted::forget() {
  if (slot_ < 0) return;
  Slot& s = slots[static_cast<std::size_t>(slot_)];
  slot_ = -1;
  for (;;) {
    int held = kHeld;
    if (s.state.compare_exchange_strong(held, kFree) || held != kRemoving) return;
    pause_briefly();  // the handler is removing it and will end the process
  }
}

PublishingOutputs::PublishingOutputs() { publishing.fetch_add(1); }

PublishingOutputs::~PublishingOutputs() {
  if (publishing.fetch_sub(1) != 1) return;
  const int signal_number = deferred_signal.exchange(0);
  if (signal_number != 0) remove_registered_and_end(signal_number);
}

}  // namespace railjoint
