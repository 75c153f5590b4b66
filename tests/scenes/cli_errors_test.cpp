// Hostile input on the command line, as a user would type it: every bad
// input exits 2 with one line naming the file or the flag, never a crash,
// a hang, a NaN in an output or a message that spans lines.

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

#include <gtest/gtest.h>

#include "tests/support/run_cli.h"
#include "tests/support/scratch_dir.h"

namespace railjoint {
namespace {

using testing_support::default_scene_path;
using testing_support::run_railjoint;
using testing_support::RunResult;
using testing_support::scratch_path;

std::string write_file(const std::string& name, const std::string& text) {
  const std::filesystem::path path = scratch_path(name);
  std::ofstream(path) << text;
  return path.string();
}

// Exit 2 and exactly one line, "railjoint: error: ..." holding `expected`.
void expect_one_line_error(const RunResult& r, const std::string& expected) {
  std::cout << "exit " << r.exit_code << ": " << r.output.substr(0, 600) << (r.output.size() > 600 ? "...\n" : "");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  EXPECT_EQ(r.output.rfind("railjoint: error: ", 0), 0u) << r.output;
  EXPECT_NE(r.output.find(expected), std::string::npos) << r.output;
}

std::string dotted_key(int levels) {
  std::string key = "a";
  for (int i = 1; i < levels; ++i) key += ".a";
  return key;
}

// Row 1 of issue 15: toml++ recursed once per level of a dotted key and
// overflowed the stack at about 30,000 levels (segmentation fault).
TEST(CliErrors, ADeeplyNestedKeyIsRefusedBeforeTheTomlParserRecurses) {
  const std::string deep_key = write_file("deep_key.toml", dotted_key(50000) + " = 1\n");
  expect_one_line_error(run_railjoint("analytic " + deep_key), deep_key + ": ");
  std::string header("[");  // appended, not "[" + key: GCC 12 warns falsely (-Wrestrict) on that
  header += dotted_key(50000) + "]\n";
  const std::string deep_table = write_file("deep_table.toml", header);
  expect_one_line_error(run_railjoint("analytic " + deep_table), "nest");
  // The same through --set: its value is parsed as TOML too.
  const std::string value = write_file("deep_value.txt", "1\n" + dotted_key(50000) + " = 1");
  expect_one_line_error(run_railjoint("analytic " + default_scene_path() + " --set \"wheel.speed=$(cat " + value + ")\""),
                        "wheel.speed");
}

// Row 3: CLI11's range checks let nan and inf through; the CSV was all nan.
TEST(CliErrors, NumberFlagsMustBeFiniteAndBounded) {
  const std::string csv = scratch_path("history.csv").string();
  // (0x10: strtod reads hexadecimal, a decimal flag must not.)
  for (const char* value : {"nan", "inf", "-inf", "1e308", "-1", "0x10", "10mm"}) {
    expect_one_line_error(run_railjoint("analytic " + default_scene_path() + " --csv " + csv + " --before-mm " + value),
                          "--before-mm");
    expect_one_line_error(run_railjoint("analytic " + default_scene_path() + " --csv " + csv + " --after-mm " + value),
                          "--after-mm");
  }
  EXPECT_FALSE(std::filesystem::exists(csv));
  // Finite but off the rails: the default 1 m rail starts 0.494 m before the
  // impact (the wheel centre 5.9 mm past the V, its contact R sin(beta/2) =
  // 7.1 mm behind it); 600 mm before it the "history" pivoted about the
  // rail's far end (zdot 10 m/s) instead.
  expect_one_line_error(run_railjoint("analytic " + default_scene_path() + " --csv " + csv + " --before-mm 600"),
                        "--before-mm");
  expect_one_line_error(run_railjoint("analytic " + default_scene_path() + " --csv " + csv + " --after-mm 600"),
                        "--after-mm");
  const RunResult on_rails =
      run_railjoint("analytic " + default_scene_path() + " --csv " + csv + " --before-mm 480 --after-mm 480 --samples 5");
  EXPECT_EQ(on_rails.exit_code, 0) << on_rails.output;
}

// Row 9: CLI11's own errors exited 105/106 with two lines.
TEST(CliErrors, ParserErrorsAreOneLineWithExitCode2) {
  expect_one_line_error(run_railjoint("analytic " + default_scene_path() + " --samples 1"), "--samples");
  expect_one_line_error(run_railjoint("render " + default_scene_path()), "--out is required");
  expect_one_line_error(run_railjoint("analytic " + default_scene_path() + " --frobnicate"), "--frobnicate");
  expect_one_line_error(run_railjoint("analytic"), "scene is required");
  // A mistyped command is named, with the one meant (issue 29, item 6).
  expect_one_line_error(run_railjoint("flatten"), "unknown command 'flatten'; the commands are analytic, simulate");
  expect_one_line_error(run_railjoint("analytc"), "unknown command 'analytc' (did you mean 'analytic'?)");
  expect_one_line_error(run_railjoint("study convergence " + default_scene_path() + " --repeats 0"), "--repeats");
  expect_one_line_error(run_railjoint(""), "subcommand");
}

// Issue 29, item 5: `analytic --set render.view=top` changed nothing and said nothing.
TEST(CliErrors, ASetIntoASectionTheCommandDoesNotReadIsRefused) {
  expect_one_line_error(run_railjoint("analytic " + default_scene_path() + " --set render.view=top"),
                        "key 'render.view': analytic does not read [render], so this --set changes nothing; it "
                        "reads [joint], [wheel]");
  expect_one_line_error(run_railjoint("mesh " + default_scene_path() + " --set sim.time_step=1e-5 --out " +
                                      scratch_path("unread.obj").string()),
                        "key 'sim.time_step': mesh does not read [sim]");
  // The second independent audit (2026-11-29): simulate took a --set of the
  // local model's keys and pressure one of the renderer's, changing nothing.
  expect_one_line_error(run_railjoint("simulate " + default_scene_path() + " --set contact_patch.steps=5"),
                        "key 'contact_patch.steps': simulate does not read [contact_patch]");
  expect_one_line_error(run_railjoint("pressure " + std::string(RAILJOINT_SOURCE_DIR) +
                                      "/scenes/pressure/table6_1.toml --set render.view=top"),
                        "key 'render.view': pressure does not read [render]");
}

TEST(CliErrors, VersionPrintsAndExits0) {
  const RunResult r = run_railjoint("--version");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.output.rfind("railjoint ", 0), 0u) << r.output;
}

TEST(CliErrors, HelpStillPrintsAndExits0) {
  for (const char* command : {"--help", "analytic --help", "study stability --help"}) {
    const RunResult r = run_railjoint(command);
    EXPECT_EQ(r.exit_code, 0) << command << "\n" << r.output;
    EXPECT_NE(r.output.find("Usage:"), std::string::npos) << r.output;
    EXPECT_GT(std::count(r.output.begin(), r.output.end(), '\n'), 5) << r.output;
  }
  // Help that cannot be written (stdout on a full disk) is a failed run too.
  if (!std::filesystem::exists("/dev/full")) return;
  const RunResult lost = testing_support::run_shell("(" + std::string(RAILJOINT_EXE) + " --help > /dev/full)");
  EXPECT_EQ(lost.exit_code, 1) << lost.output;
  EXPECT_NE(lost.output.find("standard output: cannot write the report"), std::string::npos) << lost.output;
}

// Row 5: a newline in a key split the "one-line" error; an escape character
// reached the terminal raw.
TEST(CliErrors, ControlCharactersInKeysValuesAndPathsAreEscaped) {
  const std::string key = write_file("newline_key.toml", "[joint]\n\"a\\nb\\u001b[31m\" = 1\n");
  expect_one_line_error(run_railjoint("analytic " + key), "key 'joint.a\\nb\\x1b[31m': unknown key");
  const std::string value = write_file("escape_value.toml", "[joint]\nkind = \"\\u001b[2J\\u009b\"\n");
  expect_one_line_error(run_railjoint("analytic " + value), "got \"\\x1b[2J\\u009b\"");
  const RunResult path = run_railjoint("analytic \"$(printf 'no\\nsuch\\033.toml')\"");
  expect_one_line_error(path, "no\\nsuch\\x1b.toml: no such scene file");
  const RunResult flag = run_railjoint("analytic " + default_scene_path() + " \"$(printf -- '--x\\ny')\"");
  expect_one_line_error(flag, "--x\\ny");
  for (const RunResult* r : {&path, &flag}) EXPECT_EQ(r->output.find('\033'), std::string::npos);
}

// Issue 40, item 7: a line break in a --set value dropped what followed it:
// `--set $'wheel.speed=30\njoint.beta=0.9'` ran at speed 30 with beta 0.03,
// exit 0.
TEST(CliErrors, ASetWithALineBreakIsRefused) {
  const RunResult r = run_railjoint("analytic " + default_scene_path() +
                                    " --set \"$(printf 'wheel.speed=30\\njoint.beta=0.9')\"");
  expect_one_line_error(r, "key 'wheel.speed=30\\njoint.beta=0.9': --set takes one section.key=value without line "
                           "breaks or other control characters");
}

// Issue 30, item 7: /proc/self/mem is a "regular file" of size 0 whose read
// fails (EIO); the failed read gave an empty text, and an empty scene is all
// defaults: `analytic /proc/self/mem` reported the default scene, exit 0.
// The same for a sweep's base scene.
TEST(CliErrors, AnInputFileThatCannotBeReadIsAnErrorNotAnEmptyScene) {
  ASSERT_TRUE(std::filesystem::is_regular_file("/proc/self/mem"));
  expect_one_line_error(run_railjoint("analytic /proc/self/mem"), "/proc/self/mem: cannot read scene file: ");
  const std::string sweep = write_file("unreadable_base.toml",
                                       "name = \"unreadable_base\"\nbase = \"/proc/self/mem\"\nrun = [\"analytic\"]\n"
                                       "[axes]\n\"wheel.speed\" = [10.0, 20.0]\n");
  expect_one_line_error(run_railjoint("sweep " + sweep + " --out " + scratch_path("unreadable_base_out").string()),
                        "/proc/self/mem: cannot read scene file: ");
}

std::string source_file(const std::string& relative) { return std::string(RAILJOINT_SOURCE_DIR) + "/" + relative; }

// Issue 40, item 11: two keys that disagree blame the one the user typed
// (--set) and name the other with where it came from, not a default or a
// file key the user never touched.
TEST(CliErrors, AConflictBlamesTheKeyTypedOnTheCommandLine) {
  // A 1e-12 m wheel cannot hold the default margin (1e-6 m) inside its
  // half width: it blamed sim.margin, a default, asking for a margin below
  // 2.5e-13 m, under the 1e-9 m its own range allows.
  const RunResult narrow = run_railjoint("simulate " + default_scene_path() + " --set wheel.width=1e-12");
  expect_one_line_error(narrow, "key 'wheel.width': must be 0 (a thin disc) or > 4 sim.margin = 4e-06 m");
  EXPECT_NE(narrow.output.find("sim.margin = 1e-06 m, the default"), std::string::npos) << narrow.output;
  // A 60E1 head on an inertial scene with a level approach: it blamed
  // sim.flat_approach, which the file gives (the analytic tops have none).
  const RunResult head =
      run_railjoint("simulate " +
                    write_file("inertial_rigid.toml", "[sim]\nmode = \"inertial\"\nflat_approach = 0.05\n") +
                    " --set joint.rail_profile=60E1");
  expect_one_line_error(head,
                        "key 'joint.rail_profile': cannot be simulated with sim.flat_approach = 0.05 (in the file)");
  // Hertz's patch size on a file that gives the patch: it blamed contact_patch.length.
  const RunResult size = run_railjoint("pressure " + source_file("scenes/pressure/table6_1.toml") +
                                       " --set contact_patch.size=hertz");
  expect_one_line_error(size, "key 'contact_patch.size': conflicts with contact_patch.length, contact_patch.width in "
                              "the file");
  EXPECT_NE(size.output.find("--unset contact_patch.length --unset contact_patch.width"), std::string::npos)
      << size.output;
  // What the message proposes works.
  const RunResult unset = run_railjoint("pressure " + source_file("scenes/pressure/table6_1.toml") +
                                        " --set contact_patch.size=hertz --unset contact_patch.length "
                                        "--unset contact_patch.width");
  EXPECT_EQ(unset.exit_code, 0) << unset.output;
  // The kinematic mode on a force scene: it blamed the file's sim.wheel_load,
  // then (that dropped) its contact.law.
  const std::string force_scene = source_file("scenes/forces/discrete_track.toml");
  expect_one_line_error(run_railjoint("simulate " + force_scene + " --set sim.mode=kinematic"),
                        "key 'sim.mode': conflicts with sim.wheel_load in the file");
  expect_one_line_error(run_railjoint("simulate " + force_scene + " --set sim.mode=kinematic --unset sim.wheel_load"),
                        "key 'sim.mode': must be \"inertial\" with contact.law = \"hertz\" (in the file)");
  // Both keys typed in the same place: the key that changes nothing, as before.
  const RunResult both = run_railjoint("pressure " + source_file("scenes/pressure/table6_1.toml") +
                                       " --set contact_patch.size=hertz --set contact_patch.length=0.02");
  expect_one_line_error(both, "key 'contact_patch.length': only applies to size = \"given\"");
}

// Issue 40, item 8: this force run factorised a dense matrix of its 8,529
// track nodes (past 60 s) before it stepped them all 447,917 times. The work
// (track nodes x steps) is bounded up front and refused by a key the user
// typed, with a value that fits. By hand: the beam reaches the wheel's 39 m
// (its approach; the run-out is 0.02 s x 200 m/s = 4 m) and 16 / beta_f
// beyond, beta_f = (k_f / 4 EI)^(1/4) with k_f = (1e5 || 1e5 N/m) / 0.2 m =
// 2.5e5 N/m^2: 179.95 m, so 218.95 m each way, 1095 bays of 8 nodes, 2 x
// 1095 x 8 + 1 = 17521 nodes; (39 m / 200 m/s + 0.02 s) / 4.8e-7 s = 447,917
// steps; 7.8e9 node-steps. The step cannot grow (the rail's stiffest mode
// allows 1 / omega = h^2 / 4 sqrt(mu / EI) = 4.9e-7 s at h = 0.025 m), so
// the first key that can bring it within is the approach: 2.52 m gives a
// reach of 4 m (the run-out's), 920 bays, 14721 nodes x 67,917 steps = 1e9.
TEST(CliErrors, AForceRunTooBigForItsBudgetIsRefusedByKey) {
  const std::string keys =
      " --set joint.length=100 --set sim.approach_distance=39 --set track.sleeper_spacing=0.2"
      " --set track.bending_stiffness=1e9 --set track.mass_per_length=1e4 --set track.pad_stiffness=1e5"
      " --set track.ballast_stiffness=1e5 --set sim.force_time_step=4.8e-7 --set wheel.speed=200";
  const RunResult big = run_railjoint("simulate " + source_file("scenes/forces/discrete_track.toml") + keys);
  expect_one_line_error(big, "key 'sim.approach_distance': must be <= 2.52 m");
  EXPECT_NE(big.output.find("1e+09 node-steps"), std::string::npos) << big.output;
  EXPECT_NE(big.output.find("17521 nodes"), std::string::npos) << big.output;
  EXPECT_NE(big.output.find("447917 steps"), std::string::npos) << big.output;
}

}  // namespace
}  // namespace railjoint
