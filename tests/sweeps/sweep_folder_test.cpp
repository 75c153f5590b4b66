// The output folder of a sweep as other processes and files leave it (issue
// 30): one writer at a time, only regular files read, and a resume that takes
// no line for a finished case unless it is that case's whole row.

#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "scenes/sweeps/case_models.h"
#include "scenes/sweeps/sweep_runner.h"
#include "support/input_error.h"
#include "tests/support/run_cli.h"
#include "tests/sweeps/sweep_test_support.h"

namespace railjoint {
namespace {

namespace fs = std::filesystem;
using testing_support::read_csv;
using testing_support::RunResult;
using testing_support::run_railjoint;
using testing_support::run_shell;
using testing_support::temporary_folder;
using testing_support::write_sweep;

// 12 analytic cases: microseconds each.
const char* kSweep = R"(run = ["analytic"]
[axes]
"joint.theta_deg" = [30.0, 60.0, 90.0]
"wheel.y" = { from = 0.0, to = 0.015, count = 4 }
)";

SweepSummary run(const std::string& sweep_path, const fs::path& out) {
  SweepRunOptions options;
  options.out_dir = out;
  options.jobs = 1;
  options.progress = false;
  return run_sweep(load_sweep_file(sweep_path, case_model_names()), options);
}

// The message of the InputError a run on `out` throws ("" when it runs).
std::string refusal(const std::string& sweep_path, const fs::path& out) {
  try {
    run(sweep_path, out);
  } catch (const InputError& error) {
    std::cout << error.what() << "\n";
    return error.what();
  }
  return "";
}

// A second process holding the folder's lock, as a running sweep (or a
// killed mpirun's rank 0 still writing) holds it: a run on the folder is
// refused, naming the holder's pid, until the holder dies (kill -9 too).
TEST(SweepFolder, ASecondWriterIsRefusedUntilTheFirstDies) {
  const fs::path dir = temporary_folder("sweep_folder_lock");
  const std::string sweep = write_sweep(dir, "s.toml", kSweep);
  const fs::path out = dir / "out";
  fs::create_directories(out);
  int ready[2];
  ASSERT_EQ(pipe(ready), 0);
  const pid_t holder = fork();
  ASSERT_GE(holder, 0);
  if (holder == 0) {
    const int fd = open((out / ".railjoint.lock").c_str(), O_RDWR | O_CREAT, 0644);
    if (fd < 0 || flock(fd, LOCK_EX) != 0) _exit(1);
    const std::string pid = std::to_string(getpid()) + "\n";
    if (write(fd, pid.data(), pid.size()) < 0) _exit(1);
    if (write(ready[1], "x", 1) != 1) _exit(1);
    for (;;) pause();
  }
  char byte = 0;
  ASSERT_EQ(read(ready[0], &byte, 1), 1);
  const RunResult second = run_railjoint("sweep " + sweep + " --jobs 1 --out " + out.string());
  std::cout << second.output;
  EXPECT_EQ(second.exit_code, 2);
  EXPECT_EQ(second.output, "railjoint: error: " + out.string() + ": key '--out': is in use: another railjoint (pid " +
                               std::to_string(holder) +
                               ") is writing this sweep's results here; wait for it to end, or use another --out\n");
  EXPECT_FALSE(fs::exists(out / "results.csv")) << "the refused run wrote nothing";
  kill(holder, SIGKILL);
  waitpid(holder, nullptr, 0);
  close(ready[0]);
  close(ready[1]);
  const RunResult after = run_railjoint("sweep " + sweep + " --jobs 1 --out " + out.string());
  EXPECT_EQ(after.exit_code, 0) << after.output << " (the kernel drops a dead holder's lock)";
  EXPECT_EQ(read_csv(out / "results.csv").size(), 13u);
}

// A FIFO or a device under the names a sweep reads is refused by name, at
// once (a FIFO hung a resume; a link to /dev/full grew without end).
TEST(SweepFolder, OnlyRegularFilesAreRead) {
  const fs::path dir = temporary_folder("sweep_folder_special");
  const std::string sweep = write_sweep(dir, "s.toml", kSweep);
  const auto refused = [&](const fs::path& out, const std::string& name) {
    const RunResult r = run_shell("timeout 60 " + std::string(RAILJOINT_EXE) + " sweep " + sweep + " --jobs 1 --out " +
                                  out.string() + " 2>&1 < /dev/null");
    std::cout << r.output;
    EXPECT_EQ(r.exit_code, 2) << name;
    EXPECT_NE(r.output.find("key '--out': its " + name + " is "), std::string::npos) << name;
  };
  fs::create_directories(dir / "fifo_manifest");
  ASSERT_EQ(mkfifo((dir / "fifo_manifest" / "sweep.json").c_str(), 0644), 0);
  refused(dir / "fifo_manifest", "sweep.json");

  fs::create_directories(dir / "full_manifest");
  fs::create_symlink("/dev/full", dir / "full_manifest" / "sweep.json");
  refused(dir / "full_manifest", "sweep.json");

  ASSERT_EQ(run_railjoint("sweep " + sweep + " --jobs 1 --out " + (dir / "zero").string()).exit_code, 0);
  fs::remove(dir / "zero" / "results.csv");
  fs::create_symlink("/dev/zero", dir / "zero" / "results.csv");
  refused(dir / "zero", "results.csv");

  ASSERT_EQ(run_railjoint("sweep " + sweep + " --jobs 1 --out " + (dir / "fifo_rows").string()).exit_code, 0);
  fs::remove(dir / "fifo_rows" / "results.csv");
  ASSERT_EQ(mkfifo((dir / "fifo_rows" / "results.csv").c_str(), 0644), 0);
  refused(dir / "fifo_rows", "results.csv");
}

// results.csv's lines, each with its newline.
std::vector<std::string> lines_of(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line + "\n");
  return lines;
}

void write_lines(const fs::path& path, const std::vector<std::string>& lines) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  for (const std::string& line : lines) out << line;
}

// Rows in the middle of results.csv that are not their case's whole row (cut
// short, one field more, NUL bytes, another case's values under a number)
// were taken as done; each is refused now, naming its line.
TEST(SweepFolder, ResumeRefusesARowThatIsNotItsCasesWholeRow) {
  const fs::path dir = temporary_folder("sweep_folder_rows");
  const std::string sweep = write_sweep(dir, "s.toml", kSweep);
  ASSERT_EQ(run(sweep, dir / "good").ran, 12u);
  const std::vector<std::string> good = lines_of(dir / "good" / "results.csv");
  ASSERT_EQ(good.size(), 13u);

  const auto damaged = [&](const std::string& name, const std::string& line_5) {
    const fs::path out = dir / name;
    fs::create_directories(out);
    fs::copy_file(dir / "good" / "sweep.json", out / "sweep.json");
    std::vector<std::string> lines = good;
    lines[4] = line_5;  // case 3's row, line 5 of the file
    write_lines(out / "results.csv", lines);
    const std::string message = refusal(sweep, out);
    EXPECT_NE(message.find("key '--out': line 5 "), std::string::npos) << name << ": " << message;
    return message;
  };
  const std::string row = good[4].substr(0, good[4].size() - 1);
  EXPECT_NE(damaged("cut", row.substr(0, row.size() / 2) + "\n").find("fields"), std::string::npos);
  EXPECT_NE(damaged("extra", row + ",1\n").find("fields"), std::string::npos);
  EXPECT_NE(damaged("nul", row.substr(0, 10) + std::string(4, '\0') + row.substr(14) + "\n").find("NUL"),
            std::string::npos);
  // Case 7's row with case 3's number: the right shape, the wrong values.
  std::string moved = "3";  // (+= rather than "3" + ...: GCC 12 warns falsely, -Wrestrict)
  moved += good[8].substr(good[8].find(','));
  EXPECT_NE(damaged("moved", moved).find("case 3's values"), std::string::npos);
  // The whole rows still resume: the folder as it was runs nothing.
  EXPECT_EQ(run(sweep, dir / "good").ran, 0u);
}

}  // namespace
}  // namespace railjoint
