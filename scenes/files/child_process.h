#pragma once
// A helper program (a matplotlib figure script) run to completion as a child
// of railjoint: without a shell (arguments as a list), in a process group of
// its own so that railjoint alone decides its fate, and never outliving
// railjoint: killed with its group and waited for when railjoint is
// interrupted (interrupted_run.h), and sent SIGKILL by the kernel when
// railjoint dies any other way (PR_SET_PDEATHSIG). Its standard input is
// /dev/null, its standard output railjoint's; its standard error is kept to
// say why it failed.

#include <string>
#include <vector>

namespace railjoint {

struct ChildOutcome {
  bool succeeded = false;  ///< exited with status 0
  std::string how;         ///< "exit status 1", "killed by signal 9", "cannot start: ..."
  std::string last_error;  ///< the last non-empty line it wrote to standard error
};

/// Runs `program` (a path; not searched on PATH) with `arguments` and waits
/// for it. Never throws for the child's own failure: the outcome says it.
ChildOutcome run_child(const std::string& program, const std::vector<std::string>& arguments);

}  // namespace railjoint
