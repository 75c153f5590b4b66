// Start-up: whole `railjoint` processes (--version, analytic and simulate on
// the default scene, --json) against a do-nothing program linked to Bullet
// and toml++ only (startup_reference.cpp), each started directly (no shell)
// and waited for; the median wall time and peak resident memory of --runs
// runs, and the ratio to the do-nothing program (issue 26's targets:
// analytic within 2x, simulate within 3x). Not a test: numbers of the
// machine it runs on (quote the load average printed with them).
//
//   build/tests/benchmarks/railjoint_startup_time [--runs N]

#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

extern char** environ;

namespace {

struct Sample {
  double wall_s = 0.0;
  double max_rss_MiB = 0.0;
};

// Runs the program with its output sent to /dev/null; exits on a failure
// (the timing of a failing command means nothing).
Sample run(const std::vector<std::string>& command) {
  std::vector<char*> argv;
  for (const std::string& word : command) argv.push_back(const_cast<char*>(word.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  const auto start = std::chrono::steady_clock::now();
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  int status = 0;
  rusage usage{};
  if (spawned != 0 || wait4(pid, &status, 0, &usage) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::fprintf(stderr, "failed: %s\n", command[0].c_str());
    std::exit(1);
  }
  Sample s;
  s.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  s.max_rss_MiB = static_cast<double>(usage.ru_maxrss) / 1024.0;
  return s;
}

Sample median(const std::vector<std::string>& command, int runs) {
  std::vector<double> wall, rss;
  run(command);  // once to warm the page cache
  for (int i = 0; i < runs; ++i) {
    const Sample s = run(command);
    wall.push_back(s.wall_s);
    rss.push_back(s.max_rss_MiB);
  }
  std::sort(wall.begin(), wall.end());
  std::sort(rss.begin(), rss.end());
  return {wall[wall.size() / 2], rss[rss.size() / 2]};
}

}  // namespace

int main(int argc, char** argv) {
  int runs = 21;
  for (int i = 1; i + 1 < argc; ++i) {
    if (std::string(argv[i]) == "--runs") runs = std::max(1, std::atoi(argv[i + 1]));
  }
  const std::string scene = RAILJOINT_SOURCE_DIR "/scenes/default.toml";
  const std::vector<std::pair<std::string, std::vector<std::string>>> commands = {
      {"do-nothing (Bullet + toml++)", {RAILJOINT_STARTUP_REFERENCE}},
      {"railjoint --version", {RAILJOINT_EXE, "--version"}},
      {"railjoint analytic default --json", {RAILJOINT_EXE, "analytic", scene, "--json"}},
      {"railjoint simulate default --json", {RAILJOINT_EXE, "simulate", scene, "--json"}},
  };
  std::ifstream load("/proc/loadavg");
  std::string one, five, fifteen;
  load >> one >> five >> fifteen;
  std::printf("start-up, %d runs each, medians; load average %s %s %s\n\n", runs, one.c_str(), five.c_str(),
              fifteen.c_str());
  std::printf("| command | wall [ms] | peak memory [MiB] | wall / do-nothing |\n|---|---:|---:|---:|\n");
  double reference_s = 0.0;
  for (const auto& [name, command] : commands) {
    const Sample s = median(command, runs);
    if (reference_s == 0.0) reference_s = s.wall_s;
    std::printf("| %s | %.1f | %.1f | %.2f |\n", name.c_str(), 1e3 * s.wall_s, s.max_rss_MiB, s.wall_s / reference_s);
  }
  return 0;
}
