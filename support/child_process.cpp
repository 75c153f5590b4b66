#include "support/child_process.h"

#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <fstream>
#include <iostream>

#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace railjoint {

namespace {

// Enough for a Python traceback's last lines.
constexpr std::size_t kKeptErrorBytes = 8192;

// Process groups of running children (0: free): a figure script or ffmpeg at a time.
constexpr int kChildSlots = 8;
std::array<std::atomic<pid_t>, kChildSlots> children{};

int hold_until_interrupted(pid_t group_leader) {
  for (int i = 0; i < kChildSlots; ++i) {
    pid_t none = 0;
    if (children[static_cast<std::size_t>(i)].compare_exchange_strong(none, group_leader)) return i;
  }
  return -1;  // not held: the child still dies with railjoint (PR_SET_PDEATHSIG)
}

std::string last_non_empty_line(const std::string& text) {
  std::size_t end = text.size();
  while (end > 0) {
    const std::size_t start = text.rfind('\n', end - 1);
    const std::size_t from = start == std::string::npos ? 0 : start + 1;
    const std::string line = text.substr(from, end - from);
    if (line.find_first_not_of(" \t\r") != std::string::npos) return line;
    if (start == std::string::npos) break;
    end = start;
  }
  return {};
}

// Between fork and exec only async-signal-safe calls: another thread may
// have held malloc's lock when the process was copied.
[[noreturn]] void become_child(const char* program, char* const argv[], int input_fd, int error_fd,
                               bool output_to_error, pid_t parent) {
  setpgid(0, 0);
  prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (getppid() != parent) _exit(127);  // railjoint died before the line above
  // railjoint's handlers would remove its files: the defaults until exec.
  for (const int signal_number : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction current {};
    if (sigaction(signal_number, nullptr, &current) == 0 && current.sa_handler != SIG_IGN) {
      struct sigaction by_default {};
      by_default.sa_handler = SIG_DFL;
      sigaction(signal_number, &by_default, nullptr);
    }
  }
  sigset_t none;
  sigemptyset(&none);
  sigprocmask(SIG_SETMASK, &none, nullptr);
  dup2(input_fd, STDIN_FILENO);
  if (output_to_error) dup2(error_fd, STDOUT_FILENO);
  dup2(error_fd, STDERR_FILENO);
  execv(program, argv);
  _exit(127);
}

}  // namespace

ChildProcess::ChildProcess(const std::string& program, const std::vector<std::string>& arguments,
                           ChildStreams streams)
    : error_log_(std::move(streams.error_log)) {
  std::vector<std::string> words = {program};
  words.insert(words.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);

  // All close-on-exec: a later child must not hold this one's input open.
  int error_pipe[2];
  int input_pipe[2] = {-1, -1};
  if (pipe2(error_pipe, O_CLOEXEC) != 0) {
    start_error_ = std::strerror(errno);
    return;
  }
  if (streams.input_from_railjoint && pipe2(input_pipe, O_CLOEXEC) != 0) {
    start_error_ = std::strerror(errno);
    close(error_pipe[0]);
    close(error_pipe[1]);
    return;
  }
  const int input_end = streams.input_from_railjoint ? input_pipe[0] : open("/dev/null", O_RDONLY | O_CLOEXEC);
  // Whatever railjoint printed so far comes before what the child prints.
  std::cout.flush();
  std::fflush(nullptr);
  // No signal handled between fork and the child's registration below.
  sigset_t all, previous;
  sigfillset(&all);
  pthread_sigmask(SIG_SETMASK, &all, &previous);
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid == 0) become_child(program.c_str(), argv.data(), input_end, error_pipe[1], streams.output_to_error, parent);
  const int fork_error = errno;
  if (pid > 0) {
    setpgid(pid, pid);  // also here: the group exists before anyone signals it
    slot_ = hold_until_interrupted(pid);
  }
  pthread_sigmask(SIG_SETMASK, &previous, nullptr);
  close(error_pipe[1]);
  if (input_end >= 0) close(input_end);
  if (pid < 0) {
    close(error_pipe[0]);
    if (input_pipe[1] >= 0) close(input_pipe[1]);
    start_error_ = std::strerror(fork_error);
    return;
  }
  pid_ = pid;
  input_fd_ = input_pipe[1];
  // Read while it runs: a child blocked on a full stderr pipe would never read its input.
  error_reader_ = std::thread([this, fd = error_pipe[0]] { read_errors(fd); });
}

ChildProcess::~ChildProcess() { wait(); }

void ChildProcess::read_errors(int fd) {
  std::ofstream log;  // opened at the child's first word: a silent child leaves no log
  char buffer[4096];
  for (;;) {
    const ssize_t n = read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    if (!error_log_.empty()) {
      if (!log.is_open()) log.open(error_log_, std::ios::binary | std::ios::app);
      log.write(buffer, n);
      log.flush();  // best effort: on a full disk the kept tail still says why
    }
    errors_.append(buffer, static_cast<std::size_t>(n));
    if (errors_.size() > 2 * kKeptErrorBytes) errors_.erase(0, errors_.size() - kKeptErrorBytes);
  }
  close(fd);
}

int ChildProcess::write_input(const void* data, std::size_t size) {
  if (input_fd_ < 0) return EBADF;
  // A closed pipe (the child died) must be an error from write(), not SIGPIPE:
  // held back on this thread while it writes, and taken if the write raised it.
  sigset_t pipe_signal, previous;
  sigemptyset(&pipe_signal);
  sigaddset(&pipe_signal, SIGPIPE);
  pthread_sigmask(SIG_BLOCK, &pipe_signal, &previous);
  const char* at = static_cast<const char*>(data);
  int error = 0;
  while (size > 0) {
    const ssize_t n = ::write(input_fd_, at, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      error = n < 0 ? errno : EIO;
      if (error == EPIPE) {
        const timespec no_wait{};
        sigtimedwait(&pipe_signal, nullptr, &no_wait);
      }
      break;
    }
    at += n;
    size -= static_cast<std::size_t>(n);
  }
  pthread_sigmask(SIG_SETMASK, &previous, nullptr);
  return error;
}

ChildOutcome ChildProcess::wait() {
  if (waited_) return outcome_;
  waited_ = true;
  if (!started()) {
    outcome_.how = "cannot start: " + start_error_;
    return outcome_;
  }
  if (input_fd_ >= 0) close(input_fd_);
  input_fd_ = -1;
  error_reader_.join();
  outcome_.last_error = last_non_empty_line(errors_);
  // Waited for without reaping, then no longer held, then reaped: the pid
  // the signal handler would kill is never one the system reused.
  siginfo_t info{};
  while (waitid(P_PID, static_cast<id_t>(pid_), &info, WEXITED | WNOWAIT) != 0 && errno == EINTR) {
  }
  if (slot_ >= 0) children[static_cast<std::size_t>(slot_)].store(0);
  slot_ = -1;
  int status = 0;
  pid_t reaped;
  while ((reaped = waitpid(pid_, &status, 0)) < 0 && errno == EINTR) {
  }
  if (reaped < 0) {
    outcome_.how = std::string("not waited for: ") + std::strerror(errno);
  } else if (WIFEXITED(status)) {
    outcome_.exit_status = WEXITSTATUS(status);
    outcome_.how = "exit status " + std::to_string(outcome_.exit_status);
  } else if (WIFSIGNALED(status)) {
    outcome_.how = "killed by signal " + std::to_string(WTERMSIG(status));
  }
  return outcome_;
}

ChildOutcome run_child(const std::string& program, const std::vector<std::string>& arguments) {
  return ChildProcess(program, arguments).wait();
}

void kill_children_of_interrupted_run() {
  for (std::atomic<pid_t>& child : children) {
    const pid_t pid = child.exchange(0);
    if (pid <= 0) continue;
    kill(-pid, SIGKILL);
    while (waitpid(pid, nullptr, 0) < 0 && errno == EINTR) {
    }
  }
}

}  // namespace railjoint
