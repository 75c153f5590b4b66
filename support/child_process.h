#pragma once
// The one way railjoint starts a helper program (a matplotlib figure script,
// ffmpeg): without a shell (arguments as a list), in a process group of its
// own so that railjoint alone decides its fate, and never outliving
// railjoint: killed with its group and waited for when railjoint is
// interrupted (kill_children_of_interrupted_run, called by the signal
// handler of support/interrupted_run.h), and sent SIGKILL by the kernel
// when the thread that started it dies any other way (PR_SET_PDEATHSIG). Its
// standard error is read on a thread of its own while it runs and its last
// line kept, to say why it failed.

#include <cstddef>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include <sys/types.h>

namespace railjoint {

struct ChildOutcome {
  int exit_status = -1;    ///< -1 when it did not exit (killed, not started, not waited for)
  std::string how;         ///< "exit status 1", "killed by signal 9", "cannot start: ..."
  std::string last_error;  ///< the last non-empty line it wrote to standard error
  bool succeeded() const { return exit_status == 0; }
};

struct ChildStreams {
  bool input_from_railjoint = false;  ///< standard input a pipe fed by write_input(); else /dev/null
  bool output_to_error = false;       ///< standard output joins standard error; else railjoint's
  std::filesystem::path error_log;    ///< if set, standard error is also appended there, opened at its first byte
};

class ChildProcess {
 public:
  /// Starts `program` (a path; not searched on PATH) with `arguments`. Never
  /// throws for the child's own failure: start_error() or wait() says it.
  ChildProcess(const std::string& program, const std::vector<std::string>& arguments, ChildStreams streams = {});
  ~ChildProcess();  ///< wait(), its outcome dropped
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  bool started() const { return pid_ > 0; }
  const std::string& start_error() const { return start_error_; }  ///< why it did not start (strerror)
  /// Writes all of `data` to its standard input; 0, or the errno of the write
  /// that failed (EPIPE when it closed its input, raising no SIGPIPE).
  int write_input(const void* data, std::size_t size);
  /// Closes its standard input, reads its standard error to the end and reaps it.
  ChildOutcome wait();

 private:
  void read_errors(int fd);

  pid_t pid_ = -1;
  int slot_ = -1;  ///< its place among the children killed on interruption
  int input_fd_ = -1;
  std::filesystem::path error_log_;
  std::string errors_;  ///< the last few kB of its standard error
  std::thread error_reader_;
  std::string start_error_;
  bool waited_ = false;
  ChildOutcome outcome_;
};

/// Runs `program` with `arguments` to completion: standard input /dev/null,
/// standard output railjoint's.
ChildOutcome run_child(const std::string& program, const std::vector<std::string>& arguments);

/// For the handler of an interrupting signal (async-signal-safe): kills the
/// group of every child still running (SIGKILL: none may hold the run up by
/// handling it) and waits for each, so nothing it writes appears afterwards.
void kill_children_of_interrupted_run();

}  // namespace railjoint
