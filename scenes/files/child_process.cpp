#include "scenes/files/child_process.h"

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <iostream>

#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include "scenes/files/interrupted_run.h"

namespace railjoint {

namespace {

// Enough for a Python traceback's last lines.
constexpr std::size_t kKeptErrorBytes = 8192;

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
[[noreturn]] void become_child(const char* program, char* const argv[], int error_fd, int null_fd, pid_t parent) {
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
  dup2(null_fd, STDIN_FILENO);
  dup2(error_fd, STDERR_FILENO);
  execv(program, argv);
  _exit(127);
}

}  // namespace

ChildOutcome run_child(const std::string& program, const std::vector<std::string>& arguments) {
  ChildOutcome outcome;
  std::vector<std::string> words = {program};
  words.insert(words.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);

  int error_pipe[2];
  if (pipe2(error_pipe, O_CLOEXEC) != 0) {
    outcome.how = std::string("cannot start: ") + std::strerror(errno);
    return outcome;
  }
  const int null_fd = open("/dev/null", O_RDONLY | O_CLOEXEC);
  // Whatever railjoint printed so far comes before what the child prints.
  std::cout.flush();
  std::fflush(nullptr);
  // No signal handled between fork and the child's registration below.
  sigset_t all, previous;
  sigfillset(&all);
  pthread_sigmask(SIG_SETMASK, &all, &previous);
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid == 0) become_child(program.c_str(), argv.data(), error_pipe[1], null_fd, parent);
  const int fork_error = errno;
  if (pid > 0) setpgid(pid, pid);  // also here: the group exists before anyone signals it
  KilledIfInterrupted killed_if_interrupted(pid > 0 ? pid : 0);
  pthread_sigmask(SIG_SETMASK, &previous, nullptr);
  close(error_pipe[1]);
  if (null_fd >= 0) close(null_fd);
  if (pid < 0) {
    close(error_pipe[0]);
    killed_if_interrupted.forget();
    outcome.how = std::string("cannot start: ") + std::strerror(fork_error);
    return outcome;
  }

  std::string errors;
  char buffer[4096];
  for (;;) {
    const ssize_t n = read(error_pipe[0], buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    errors.append(buffer, static_cast<std::size_t>(n));
    if (errors.size() > 2 * kKeptErrorBytes) errors.erase(0, errors.size() - kKeptErrorBytes);
  }
  close(error_pipe[0]);
  // Waited for without reaping, then no longer held, then reaped: the pid
  // the signal handler would kill is never one the system reused.
  siginfo_t info{};
  while (waitid(P_PID, static_cast<id_t>(pid), &info, WEXITED | WNOWAIT) != 0 && errno == EINTR) {
  }
  killed_if_interrupted.forget();
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  outcome.last_error = last_non_empty_line(errors);
  if (WIFEXITED(status)) {
    outcome.succeeded = WEXITSTATUS(status) == 0;
    outcome.how = "exit status " + std::to_string(WEXITSTATUS(status));
  } else if (WIFSIGNALED(status)) {
    outcome.how = "killed by signal " + std::to_string(WTERMSIG(status));
  }
  return outcome;
}

}  // namespace railjoint
