#pragma once
// Runs the real `railjoint` executable as a user would, for the CLI tests.
// The test target defines RAILJOINT_EXE (the built executable) and
// RAILJOINT_SOURCE_DIR; link it with railjoint_cli_test_support.

#include <cstdio>
#include <string>

#include <sys/wait.h>

namespace railjoint::testing_support {

struct RunResult {
  int exit_code = -1;
  std::string output;  ///< stdout and stderr together
};

/// Runs a shell command line, stdout and stderr together.
inline RunResult run_shell(const std::string& command_line) {
  const std::string command = command_line + " 2>&1";
  RunResult result;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return result;
  char buffer[4096];
  while (fgets(buffer, sizeof buffer, pipe) != nullptr) result.output += buffer;
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

/// Runs `railjoint <arguments>` through the shell (arguments are not quoted).
inline RunResult run_railjoint(const std::string& arguments) {
  return run_shell(std::string(RAILJOINT_EXE) + " " + arguments);
}

/// As run_railjoint, with every file the run writes limited to `kilobytes`
/// (the shell's ulimit -f, RLIMIT_FSIZE): railjoint ignores the SIGXFSZ
/// that would kill it, so a write past the limit fails with EFBIG, as one on
/// a full disk fails with ENOSPC.
inline RunResult run_railjoint_with_file_limit(const std::string& arguments, int kilobytes) {
  // dash's ulimit -f counts 512-byte blocks.
  return run_shell("ulimit -f " + std::to_string(2 * kilobytes) + "; exec " + std::string(RAILJOINT_EXE) + " " +
                   arguments);
}

/// The output of a `--json` run that also wrote to stderr after its report
/// (a run that measured nothing exits 1 with one line saying why): the JSON
/// object's text, and what followed it. Empty json when there is no object.
struct JsonAndTail {
  std::string json;
  std::string tail;
};

inline JsonAndTail split_json_and_tail(const std::string& output) {
  const std::size_t end = output.rfind("}\n");
  if (end == std::string::npos) return {"", output};
  return {output.substr(0, end + 1), output.substr(end + 2)};
}

/// The default scene shipped with the sources.
inline std::string default_scene_path() { return std::string(RAILJOINT_SOURCE_DIR) + "/scenes/default.toml"; }

}  // namespace railjoint::testing_support
