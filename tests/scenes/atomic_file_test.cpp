// Outputs appear whole or not at all (support/atomic_file.h,
// staging_folder.h): a write that fails (a full disk, simulated by a
// symbolic link to /dev/full or by a file-size limit on the process) exits
// non-zero naming the file and leaves neither a truncated file nor a
// temporary one behind; an older file of that name stays as it was.

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include <stdlib.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "renders/offscreen_renderer.h"
#include "support/atomic_file.h"
#include "support/input_error.h"
#include "support/staging_folder.h"
#include "support/temporary_name.h"
#include "tests/support/file_text.h"
#include "tests/support/run_cli.h"
#include "tests/support/scratch_dir.h"

namespace railjoint {
namespace {

namespace fs = std::filesystem;
using testing_support::default_scene_path;
using testing_support::run_railjoint;
using testing_support::run_railjoint_with_file_limit;
using testing_support::RunResult;
using testing_support::scratch_dir;
using testing_support::scratch_path;

std::string read(const std::filesystem::path& path) { return testing_support::file_text(path); }

std::set<std::string> names_in(const fs::path& folder) {
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder)) names.insert(entry.path().filename().string());
  return names;
}

bool have_dev_full() { return fs::exists("/dev/full"); }

TEST(AtomicFile, TheFileGetsItsNameOnlyWhenCommitted) {
  const fs::path path = scratch_path("table.csv");
  {
    AtomicFile out(path, "--csv");
    out << "a,b\n" << 1.5 << ',' << 2 << '\n';
    EXPECT_FALSE(fs::exists(path)) << "not before commit()";
    out.commit();
  }
  EXPECT_EQ(read(path), "a,b\n1.5,2\n");
  EXPECT_EQ(names_in(scratch_dir()), std::set<std::string>{"table.csv"}) << "no temporary file left";
}

TEST(AtomicFile, AnUncommittedFileLeavesTheOlderOneAndNoTrace) {
  const fs::path path = scratch_path("table.csv");
  std::ofstream(path) << "older\n";
  {
    AtomicFile out(path, "--csv");
    out << "newer, but the run failed before it was complete\n";
  }
  EXPECT_EQ(read(path), "older\n");
  EXPECT_EQ(names_in(scratch_dir()), std::set<std::string>{"table.csv"});
}

TEST(AtomicFile, AMissingFolderOrAFolderIsBadInputNamingTheFileAndOption) {
  try {
    AtomicFile out(scratch_path("no_such_folder") / "x.csv", "--csv");
    FAIL() << "no error";
  } catch (const InputError& error) {
    std::cout << error.what() << "\n";
    EXPECT_EQ(error.key(), "--csv");
    EXPECT_NE(std::string(error.what()).find("no_such_folder/x.csv"), std::string::npos);
  }
  EXPECT_THROW(AtomicFile(scratch_dir(), "--csv"), InputError);
}

TEST(AtomicFile, AWriteErrorOnADeviceIsReportedNamingTheFile) {
  if (!have_dev_full()) GTEST_SKIP() << "no /dev/full";
  AtomicFile out("/dev/full", "--csv");
  for (int i = 0; i < 100000; ++i) out << "0.123456789,";
  try {
    out.commit();
    FAIL() << "no error";
  } catch (const std::runtime_error& error) {
    std::cout << error.what() << "\n";
    EXPECT_NE(std::string(error.what()).find("/dev/full (--csv): cannot write this file: No space left on device"),
              std::string::npos);
  }
}

TEST(AtomicFile, ALinkToAFileStaysALink) {
  const fs::path target = scratch_path("real.csv");
  const fs::path link = scratch_path("link.csv");
  std::ofstream(target) << "older\n";
  fs::create_symlink(target, link);
  AtomicFile out(link, "--csv");
  out << "newer\n";
  out.commit();
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_EQ(read(target), "newer\n");
}

TEST(StagingFolder, PublishesFilesAndRemovesWhatWasNotPublished) {
  std::ofstream(scratch_path("mesh.obj")) << "older\n";
  {
    StagingFolder staging(scratch_dir(), "--out");
    std::ofstream(staging.path() / "mesh.obj") << "newer\n";
    std::ofstream(staging.path() / "mesh.mtl") << "material\n";
    std::ofstream(staging.path() / "scratch.log") << "not published\n";
    EXPECT_EQ(staging.published_text("see " + (staging.path() / "x.log").string()), "see " + (scratch_dir() / "x.log").string());
    staging.publish("mesh.obj", "mesh.obj");
    staging.publish("mesh.mtl", "mesh.mtl");
  }
  EXPECT_EQ(read(scratch_path("mesh.obj")), "newer\n");
  EXPECT_EQ(names_in(scratch_dir()), (std::set<std::string>{"mesh.mtl", "mesh.obj"}));
}

// A link to a file on another file system (tmpfs /dev/shm beside the disk
// the scratch folder is on): a rename cannot cross it ("Invalid cross-device
// link"), so the bytes are written beside the linked file and renamed there;
// the link stays a link.
TEST(StagingFolder, PublishesThroughALinkToAnotherFileSystem) {
  std::string other_pattern = "/dev/shm/railjoint-staging-test-XXXXXX";
  struct stat here {}, there {};
  if (!fs::is_directory("/dev/shm") || mkdtemp(other_pattern.data()) == nullptr) GTEST_SKIP() << "no /dev/shm";
  const fs::path other(other_pattern);
  if (stat(scratch_dir().c_str(), &here) != 0 || stat(other.c_str(), &there) != 0 || here.st_dev == there.st_dev) {
    fs::remove_all(other);
    GTEST_SKIP() << "/dev/shm is on the scratch folder's file system";
  }
  std::ofstream(other / "mesh.obj") << "older\n";
  fs::create_symlink(other / "mesh.obj", scratch_path("link.obj"));
  {
    StagingFolder staging(scratch_dir(), "--out");
    std::ofstream(staging.path() / "link.obj") << "newer\n";
    EXPECT_NO_THROW(staging.publish("link.obj", "link.obj"));
  }
  EXPECT_TRUE(fs::is_symlink(scratch_path("link.obj")));
  EXPECT_EQ(read(other / "mesh.obj"), "newer\n");
  EXPECT_EQ(names_in(other), std::set<std::string>{"mesh.obj"}) << "no temporary left beside the linked file";
  fs::remove_all(other);
}

// ---- the commands, as a user runs them (issue 15, row 4) ----

// One line naming the file and why, a non-zero exit.
void expect_write_error(const RunResult& r, const std::string& file) {
  std::cout << "exit " << r.exit_code << ": " << r.output;
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(r.output.rfind("railjoint: error: "), r.output.find("railjoint: error: ")) << "one error line";
  EXPECT_NE(r.output.find(file), std::string::npos) << r.output;
  EXPECT_TRUE(r.output.find("No space left on device") != std::string::npos ||
              r.output.find("File too large") != std::string::npos)
      << r.output;
}

TEST(WriteErrors, CsvIntoALinkToDevFullFails) {
  if (!have_dev_full()) GTEST_SKIP() << "no /dev/full";
  const fs::path csv = scratch_path("f.csv");
  fs::create_symlink("/dev/full", csv);
  expect_write_error(run_railjoint("analytic " + default_scene_path() + " --csv " + csv.string()), csv.string());
  expect_write_error(run_railjoint("analytic " + default_scene_path() + " --top-view " + csv.string()), csv.string());
  expect_write_error(run_railjoint("simulate " + default_scene_path() + " --csv " + csv.string()), csv.string());
  EXPECT_TRUE(fs::is_symlink(csv));
  EXPECT_EQ(names_in(scratch_dir()), std::set<std::string>{"f.csv"});
}

TEST(WriteErrors, AFullDiskLeavesTheOlderFileAndNoTemporaryOne) {
  // 8 kB per file: the default scene's history CSV is about 230 kB, the
  // simulated one 50 kB, the pressure traversal 140 kB.
  const fs::path csv = scratch_path("f.csv");
  for (const std::string& command : {"analytic " + default_scene_path() + " --csv " + csv.string(),
                                    "simulate " + default_scene_path() + " --csv " + csv.string(),
                                    "pressure " + std::string(RAILJOINT_SOURCE_DIR) +
                                        "/scenes/pressure/table6_1.toml --csv " + csv.string()}) {
    std::ofstream(csv) << "older\n";
    expect_write_error(run_railjoint_with_file_limit(command, 8), csv.string());
    EXPECT_EQ(read(csv), "older\n");
    EXPECT_EQ(names_in(scratch_dir()), std::set<std::string>{"f.csv"});
  }
}

// Two outputs of one command at the same path: refused before anything is
// written (exit 2, one line naming the file and both options), and no
// folder is left where the file was to go. `./f.csv` is the same path.
TEST(WriteErrors, AFileOutputAtTheSamePathAsAnotherOutputIsRefused) {
  const fs::path csv = scratch_path("f.csv");
  const std::string dotted = (scratch_dir() / "." / "f.csv").string();
  const std::string pressure =
      "pressure " + std::string(RAILJOINT_SOURCE_DIR) + "/scenes/pressure/table6_1.toml --csv " + csv.string();
  for (const auto& [command, other] :
       {std::pair{pressure + " --out " + dotted, std::string("--out")}, {pressure + " --frames " + dotted, "--frames"}}) {
    const RunResult r = run_railjoint(command);
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find(csv.string() + ": key '--csv': is also the path given to " + other), std::string::npos)
        << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    EXPECT_FALSE(fs::exists(csv)) << command;
  }
  // simulate checks its render folder only when it will draw into it.
  const RunResult r = run_railjoint("simulate " + default_scene_path() + " --set render.ffmpeg=false --csv " +
                                    csv.string() + " --render-out " + dotted);
  if (rendering_available()) {
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find(csv.string() + ": key '--csv': is also the path given to --render-out"), std::string::npos)
        << r.output;
    EXPECT_FALSE(fs::exists(csv));
  }
}

// A run ended by a signal (Ctrl-C, kill, a batch system's SIGTERM) leaves
// no hidden temporary behind: killed as soon as its 1 GB CSV's temporary
// appears (the run would take ~30 s), it removes it and ends by SIGTERM
// (exit status 143 in the shell).
TEST(WriteErrors, AnInterruptedRunLeavesNoTemporary) {
  const fs::path csv = scratch_path("f.csv");
  const std::string run = std::string(RAILJOINT_EXE) + " analytic " + default_scene_path() +
                          " --samples 10000000 --csv " + csv.string() + " > /dev/null 2>&1 & pid=$!; " +
                          "for i in $(seq 400); do ls " + scratch_dir().string() +
                          "/.f.csv.railjoint-* > /dev/null 2>&1 && break; sleep 0.025; done; " +
                          "kill -TERM $pid; wait $pid; echo \"status $?\"";
  const RunResult r = testing_support::run_shell(run);
  EXPECT_NE(r.output.find("status 143"), std::string::npos) << r.output;
  EXPECT_TRUE(names_in(scratch_dir()).empty()) << "left: " << *names_in(scratch_dir()).begin();
}

// A hangup the parent ignores (nohup, a batch system) stays ignored: the
// run goes on after SIGHUP, and SIGTERM still cleans up after it.
TEST(WriteErrors, AnIgnoredHangupStaysIgnored) {
  const fs::path csv = scratch_path("f.csv");
  const std::string run = "(trap '' HUP; exec " + std::string(RAILJOINT_EXE) + " analytic " + default_scene_path() +
                          " --samples 10000000 --csv " + csv.string() + " > /dev/null 2>&1) & pid=$!; " +
                          "for i in $(seq 400); do ls " + scratch_dir().string() +
                          "/.f.csv.railjoint-* > /dev/null 2>&1 && break; sleep 0.025; done; " +
                          "kill -HUP $pid; sleep 0.2; kill -0 $pid && echo alive after SIGHUP; " +
                          "kill -TERM $pid; wait $pid; echo \"status $?\"";
  const RunResult r = testing_support::run_shell(run);
  EXPECT_NE(r.output.find("alive after SIGHUP"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("status 143"), std::string::npos) << r.output;
  EXPECT_TRUE(names_in(scratch_dir()).empty()) << "left: " << *names_in(scratch_dir()).begin();
}

// Replacing a file keeps its permissions; a name near the 255-byte limit
// still gets a temporary of its own.
TEST(AtomicFile, KeepsTheReplacedFilesPermissionsAndTakesLongNames) {
  const fs::path secret = scratch_path("secret.csv");
  std::ofstream(secret) << "older\n";
  fs::permissions(secret, fs::perms::owner_read | fs::perms::owner_write);
  {
    AtomicFile out(secret, "--csv");
    out << "newer\n";
    out.commit();
  }
  EXPECT_EQ(read(secret), "newer\n");
  EXPECT_EQ(fs::status(secret).permissions() & fs::perms::all, fs::perms::owner_read | fs::perms::owner_write);
  // A read-only file is replaced as `mv -f` replaces it, and stays read-only.
  const fs::perms read_only = fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read;
  fs::permissions(secret, read_only);
  {
    AtomicFile out(secret, "--csv");
    out << "newest\n";
    out.commit();
  }
  EXPECT_EQ(read(secret), "newest\n");
  EXPECT_EQ(fs::status(secret).permissions() & fs::perms::all, read_only);

  const fs::path long_name = scratch_path(std::string(240, 'a') + ".csv");
  {
    AtomicFile out(long_name, "--csv");
    out << "long\n";
    out.commit();
  }
  EXPECT_EQ(read(long_name), "long\n");
}

TEST(WriteErrors, JsonOnAFullStandardOutputFails) {
  if (!have_dev_full()) GTEST_SKIP() << "no /dev/full";
  for (const std::string& command : {"analytic " + default_scene_path() + " --json",
                                    "analytic " + default_scene_path(), "simulate " + default_scene_path() + " --json"}) {
    // The redirection inside the subshell: its stderr still reaches the test.
    const RunResult r = testing_support::run_shell("(" + std::string(RAILJOINT_EXE) + " " + command +
                                                               " > /dev/full)");
    std::cout << "exit " << r.exit_code << ": " << r.output;
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.output, "railjoint: error: standard output: cannot write the report: No space left on device\n");
  }
}

TEST(WriteErrors, AMeshIsWrittenWholeOrNotAtAll) {
  const fs::path obj = scratch_path("joint.obj");
  std::ofstream(obj) << "older\n";
  expect_write_error(run_railjoint_with_file_limit("mesh " + default_scene_path() + " --wheel --out " + obj.string(), 8),
                     obj.string());
  EXPECT_EQ(read(obj), "older\n");
  EXPECT_EQ(names_in(scratch_dir()), std::set<std::string>{"joint.obj"}) << "no .mtl, no staging folder";

  const RunResult r = run_railjoint("mesh " + default_scene_path() + " --wheel --out " + obj.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(names_in(scratch_dir()), (std::set<std::string>{"joint.mtl", "joint.obj"}));
  EXPECT_NE(read(obj).find("mtllib joint.mtl"), std::string::npos) << "the published .obj names the published .mtl";

  if (!have_dev_full()) return;
  const fs::path stl = scratch_path("full.stl");
  fs::create_symlink("/dev/full", stl);
  expect_write_error(run_railjoint("mesh " + default_scene_path() + " --out " + stl.string()), stl.string());

  // An .obj that cannot be written leaves no .mtl without its mesh.
  const fs::path full_obj = scratch_path("full.obj");
  fs::create_symlink("/dev/full", full_obj);
  expect_write_error(run_railjoint("mesh " + default_scene_path() + " --out " + full_obj.string()), full_obj.string());
  EXPECT_FALSE(fs::exists(scratch_path("full.mtl"))) << "a material file beside a mesh that was not written";
}

TEST(WriteErrors, StudyTablesAreWholeOrAbsent) {
  const fs::path out = scratch_path("stability");
  const RunResult r =
      run_railjoint_with_file_limit("study stability --quick --no-figures --out " + out.string(), 1);
  expect_write_error(r, out.string() + "/stability_quick.");
  EXPECT_TRUE(names_in(out).empty()) << "a table too large for the limit is not left truncated";
}

// The pid of a process that has ended (forked, exited, reaped): nothing
// runs under it until the system hands it out again.
pid_t a_dead_pid() {
  const pid_t pid = fork();
  if (pid == 0) _exit(0);
  waitpid(pid, nullptr, 0);
  return pid;
}

TEST(TemporaryName, TheOwnerIsReadFromRailjointsOwnNamesOnly) {
  EXPECT_EQ(temporary_owner(temporary_name("f.csv", 4242, 0)), 4242);
  EXPECT_EQ(temporary_owner(temporary_name(std::string(240, 'a'), 17, 3)), 17) << "the short form of a long name";
  EXPECT_EQ(temporary_owner(".railjoint-17-3"), 17);
  for (const char* other : {"f.csv.railjoint-17-0", ".f.csv.railjoint-17-0.bak", ".f.csv.railjoint-17-", ".f.csv.railjoint--0",
                            ".f.csv.railjoint-x-0", "..railjoint-17-0", ".f.csvrailjoint-17-0", ".railjoint-staging-abc123",
                            ".f.csv.railjoint-0-0", "railjoint-17-0"}) {
    EXPECT_FALSE(temporary_owner(other).has_value()) << other;
  }
}

// Issue 30 item 8: a run killed outright (SIGKILL, the OOM killer) left its
// temporary (one was 320 MB) and nothing ever removed it. The next write
// into that folder removes the temporaries of processes that have ended,
// and nothing else: not a live process's, not a name that only looks alike,
// not a folder.
TEST(AtomicFile, RemovesTheTemporariesOfEndedRunsOnly) {
  const pid_t dead = a_dead_pid();
  const std::set<std::string> stale = {temporary_name("f.csv", dead, 0), temporary_name("g.png", dead, 2),
                                       temporary_name(std::string(240, 'b'), dead, 0)};
  const std::set<std::string> kept_files = {temporary_name("f.csv", getpid(), 7), temporary_name("f.csv", 1, 0),
                                            "f.csv.railjoint-" + std::to_string(dead) + "-0",
                                            ".f.csv.railjoint-" + std::to_string(dead) + "-0.bak", "notes.txt"};
  for (const std::string& name : stale) std::ofstream(scratch_path(name)) << "stale";
  for (const std::string& name : kept_files) std::ofstream(scratch_path(name)) << "kept";
  const std::string a_folder = temporary_name("d", dead, 0);
  fs::create_directory(scratch_path(a_folder));
  {
    AtomicFile out(scratch_path("new.csv"), "--csv");
    out << "new\n";
    out.commit();
  }
  std::set<std::string> expected = kept_files;
  expected.insert(a_folder);
  expected.insert("new.csv");
  EXPECT_EQ(names_in(scratch_dir()), expected);
}

// The same for a staging folder: a render killed outright (the campaign of
// issue 30: SIGKILL while its frames were drawn) left
// .railjoint-staging-XXXXXX with every frame, which nothing removed; its
// name carries no pid. Now it does, and the next staging folder made in that
// folder removes those of ended runs, with what they hold, and nothing else.
TEST(StagingFolder, RemovesTheStagingFoldersOfEndedRunsOnly) {
  const pid_t dead = a_dead_pid();
  std::string made = staging_folder_pattern(dead);
  made.replace(made.size() - 6, 6, "a1B2c3");
  EXPECT_EQ(staging_folder_owner(made), dead);
  for (const char* other : {".railjoint-staging-abc123", ".railjoint-staging--a1B2c3", ".railjoint-staging-17-a1B2c",
                            "railjoint-staging-17-a1B2c3", ".railjoint-staging-17-a1B2c3.bak"}) {
    EXPECT_FALSE(staging_folder_owner(other).has_value()) << other;
  }
  fs::create_directory(scratch_path(made));
  std::ofstream(scratch_path(made) / "frame_00000.png") << "frame";
  std::string alive = staging_folder_pattern(getpid());
  alive.replace(alive.size() - 6, 6, "zzzzzz");
  fs::create_directory(scratch_path(alive));
  std::ofstream(scratch_path(".railjoint-staging-abc123")) << "a file of that look";
  {
    StagingFolder staging(scratch_dir(), "--out");
    EXPECT_EQ(staging_folder_owner(staging.path().filename().string()), getpid()) << staging.path();
    EXPECT_FALSE(fs::exists(scratch_path(made)));
    EXPECT_TRUE(fs::is_directory(scratch_path(alive)));
    EXPECT_TRUE(fs::is_regular_file(scratch_path(".railjoint-staging-abc123")));
  }
}

}  // namespace
}  // namespace railjoint
