// Measured profiles in sweeps (issue 40 items 2, 3, 10) and the sweep
// file's [set] (item 13): a path is relative to the file that names it, each
// profile is read once when the sweep starts and is part of its fingerprint,
// a bad profile is a rejected row, and [set] fixes a key for every case.

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "scenes/sweeps/case_evaluator.h"
#include "scenes/sweeps/case_models.h"
#include "tests/support/cylinder_tread.h"
#include "tests/support/run_cli.h"
#include "tests/sweeps/sweep_test_support.h"

namespace railjoint {
namespace {

namespace fs = std::filesystem;
using testing_support::column;
using testing_support::CsvTable;
using testing_support::read_csv;
using testing_support::RunResult;
using testing_support::run_railjoint;
using testing_support::run_shell;
using testing_support::temporary_folder;

using railjoint::testing_support::cylinder_tread;
constexpr auto write = railjoint::testing_support::write_text_file;

// The scene of the reproducer: prof/tread.toml names its tread "tread.csv",
// beside it. A 20 mm wide wheel 15 mm off the centre line (scenario 2: its
// jump depends on the radius).
void write_profile_scene(const fs::path& dir, double radius_m) {
  write(dir / "prof" / "tread.csv", cylinder_tread(radius_m));
  write(dir / "prof" / "tread.toml", "[wheel]\nprofile = \"tread.csv\"\nwidth = 0.02\ny = 0.015\n");
}

// The jump of the same wheel as a plain cylinder (no profile file): what
// the measured cylinder must give, from the analytic command's own route.
double cylinder_exact_Ns(double radius_m, const std::string& more = "") {
  const RunResult r = run_railjoint("analytic " + testing_support::default_scene_path() +
                                    " --set wheel.width=0.02 --set wheel.y=0.015 --set wheel.radius=" +
                                    std::to_string(radius_m) + " " + more + " --json");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return nlohmann::json::parse(r.output).at("exact_Ns").get<double>();
}

RunResult sweep(const fs::path& sweep_file, const fs::path& out) {
  const RunResult r = run_railjoint("sweep " + sweep_file.string() + " --jobs 2 --out " + out.string());
  std::cout << r.output;
  return r;
}

// A measured cylinder and the exact cylinder agree to rounding on this case
// (measured 1e-12 relative); 1e-9 of the jump leaves room and is still a
// million times below the 0.3 m decoy's difference.
constexpr double kSameJump = 1e-9;

// Item 2: a sweep in another folder, base = "../prof/tread.toml", looked for
// the tread beside the sweep file: every row rejected, or a file of that
// name there used silently. The base scene's paths are its own.
TEST(SweepProfiles, TheBaseScenesProfileIsRelativeToTheBaseScene) {
  const fs::path dir = temporary_folder("sweep_profile_base");
  write_profile_scene(dir, 0.475);
  write(dir / "sweeps" / "s.toml", "base = \"../prof/tread.toml\"\nrun = [\"analytic\"]\n[axes]\n\"wheel.speed\" = [50.0]\n");
  ASSERT_EQ(sweep(dir / "sweeps" / "s.toml", dir / "out").exit_code, 0);
  const CsvTable alone = read_csv(dir / "out" / "results.csv");
  ASSERT_EQ(alone.size(), 2u);
  EXPECT_EQ(alone[1][column(alone, "verdict")], "ok") << alone[1][column(alone, "message")];
  const double expected_Ns = cylinder_exact_Ns(0.475);
  EXPECT_NEAR(std::stod(alone[1][column(alone, "analytic.exact_Ns")]), expected_Ns, kSameJump * expected_Ns);

  // A decoy of the same name beside the sweep file (a 0.3 m wheel) is not read.
  write(dir / "sweeps" / "tread.csv", cylinder_tread(0.3));
  ASSERT_EQ(sweep(dir / "sweeps" / "s.toml", dir / "out_decoy").exit_code, 0);
  const CsvTable decoy = read_csv(dir / "out_decoy" / "results.csv");
  ASSERT_EQ(decoy.size(), 2u);
  std::cout << "exact cylinder " << expected_Ns << " N s, 0.3 m decoy " << cylinder_exact_Ns(0.3) << " N s, row "
            << decoy[1][column(decoy, "analytic.exact_Ns")] << " N s\n";
  EXPECT_NEAR(std::stod(decoy[1][column(decoy, "analytic.exact_Ns")]), expected_Ns, kSameJump * expected_Ns);

  // The base scene's file missing is the sweep's error, not 1 of N rows rejected each.
  fs::remove(dir / "prof" / "tread.csv");
  const RunResult missing = sweep(dir / "sweeps" / "s.toml", dir / "out_missing");
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.output.find("prof/tread.toml: key 'wheel.profile': " +
                                fs::absolute(dir / "prof" / "tread.csv").lexically_normal().string() +
                                ": no such profile file"),
            std::string::npos)
      << missing.output;
}

// Item 2: a path in an axis or in [set] is the sweep file's.
TEST(SweepProfiles, AxisAndSetPathsAreRelativeToTheSweepFile) {
  const fs::path dir = temporary_folder("sweep_profile_axis");
  write_profile_scene(dir, 0.475);
  write(dir / "sweeps" / "wide.csv", cylinder_tread(0.5));
  write(dir / "sweeps" / "axis.toml", "base = \"../prof/tread.toml\"\nrun = [\"analytic\"]\n[axes]\n"
                                      "\"wheel.profile\" = [\"wide.csv\", \"../prof/tread.csv\"]\n");
  write(dir / "sweeps" / "set.toml", "base = \"../prof/tread.toml\"\nrun = [\"analytic\"]\n[set]\n"
                                     "\"wheel.profile\" = \"wide.csv\"\n[axes]\n\"wheel.speed\" = [50.0]\n");
  // Run from a third folder: nothing is relative to the current one.
  write(dir / "elsewhere" / "wide.csv", cylinder_tread(0.3));
  const RunResult axis = run_shell("cd " + (dir / "elsewhere").string() + " && " + RAILJOINT_EXE + " sweep ../sweeps/axis.toml --out ../out_axis");
  ASSERT_EQ(axis.exit_code, 0) << axis.output;
  const CsvTable a = read_csv(dir / "out_axis" / "results.csv");
  ASSERT_EQ(a.size(), 3u);
  EXPECT_EQ(a[1][column(a, "wheel.profile")], "wide.csv");  // the row shows the value as the sweep file gives it
  const double wide_Ns = cylinder_exact_Ns(0.5), plain_Ns = cylinder_exact_Ns(0.475);
  EXPECT_NEAR(std::stod(a[1][column(a, "analytic.exact_Ns")]), wide_Ns, kSameJump * wide_Ns);
  EXPECT_NEAR(std::stod(a[2][column(a, "analytic.exact_Ns")]), plain_Ns, kSameJump * plain_Ns);

  const RunResult set = run_shell("cd " + (dir / "elsewhere").string() + " && " + RAILJOINT_EXE + " sweep ../sweeps/set.toml --out ../out_set");
  ASSERT_EQ(set.exit_code, 0) << set.output;
  const CsvTable s = read_csv(dir / "out_set" / "results.csv");
  ASSERT_EQ(s.size(), 2u);
  EXPECT_NEAR(std::stod(s[1][column(s, "analytic.exact_Ns")]), wide_Ns, kSameJump * wide_Ns);
}

// Item 3: the sweep reads each profile once, when it starts: the cases use
// that content even when the file is gone or replaced while they run
// (269 of 4,000 rows were on the old profile after a replacement).
TEST(SweepProfiles, EachProfileIsReadOnceWhenTheSweepStarts) {
  const fs::path dir = temporary_folder("sweep_profile_once");
  write_profile_scene(dir, 0.475);
  const fs::path sweep_file = dir / "s.toml";
  write(sweep_file, "base = \"prof/tread.toml\"\nrun = [\"analytic\"]\n[axes]\n\"wheel.speed\" = [50.0]\n");
  const SweepFile sweep = load_sweep_file(sweep_file.string(), case_model_names());
  const CaseEvaluator evaluator(sweep, case_models(sweep.models));  // the sweep's start
  fs::remove(dir / "prof" / "tread.csv");
  CaseScratch scratch;
  CsvRow row;
  EXPECT_EQ(evaluator.append_row(0, scratch, row), CaseVerdict::ok) << row.str();
  write(dir / "prof" / "tread.csv", cylinder_tread(0.3));  // another profile under the same name
  CsvRow again;
  evaluator.append_row(0, scratch, again);
  std::cout << row.str() << again.str();
  const auto without_wall_ms = [](const std::string& line) { return line.substr(0, line.rfind(',')); };
  EXPECT_EQ(without_wall_ms(again.str()), without_wall_ms(row.str()));
  ASSERT_EQ(evaluator.profiles().size(), 1u);
  EXPECT_EQ(evaluator.profiles()[0].key, "wheel.profile");
  EXPECT_EQ(evaluator.profiles()[0].path, fs::absolute(dir / "prof" / "tread.csv").lexically_normal().string());
}

// Item 3: kill, change the CSV, resume gave 112-123 stale rows with exit 0.
// The profile's SHA-256 is in sweep.json: a resume on a changed profile is
// refused, naming the file and the key.
TEST(SweepProfiles, AResumeOnAChangedProfileIsRefusedByName) {
  const fs::path dir = temporary_folder("sweep_profile_resume");
  write_profile_scene(dir, 0.475);
  write(dir / "s.toml", "base = \"prof/tread.toml\"\nrun = [\"analytic\"]\n[axes]\n\"wheel.speed\" = [30.0, 50.0]\n");
  ASSERT_EQ(sweep(dir / "s.toml", dir / "out").exit_code, 0);
  const auto manifest = nlohmann::json::parse(std::ifstream(dir / "out" / "sweep.json"));
  std::cout << manifest.dump(2) << "\n";
  ASSERT_EQ(manifest.at("profiles").size(), 1u);
  EXPECT_EQ(manifest.at("profiles")[0].at("key"), "wheel.profile");
  // sha256sum of the same bytes, from outside the code under test.
  const RunResult sum = run_shell("sha256sum " + (dir / "prof" / "tread.csv").string());
  EXPECT_EQ(sum.output.substr(0, 64), manifest.at("profiles")[0].at("sha256").get<std::string>());
  EXPECT_EQ(sweep(dir / "s.toml", dir / "out").exit_code, 0);  // unchanged: resumes

  write(dir / "prof" / "tread.csv", cylinder_tread(0.3));
  const RunResult changed = sweep(dir / "s.toml", dir / "out");
  EXPECT_EQ(changed.exit_code, 2);
  EXPECT_NE(changed.output.find("the profile " + fs::absolute(dir / "prof" / "tread.csv").lexically_normal().string() +
                                " (wheel.profile) changed"),
            std::string::npos)
      << changed.output;
  EXPECT_EQ(changed.output.find('\n'), changed.output.size() - 1) << "one line";
}

// Item 10: a tread without y = 0 stopped the whole sweep (1,991 of 4,000
// rows) with Boost's message, and every rerun again. Its cases are rows
// rejected with the reason; the others run.
TEST(SweepProfiles, ATreadWithoutTheWheelsPlaneIsARejectedRow) {
  const fs::path dir = temporary_folder("sweep_profile_bad");
  write_profile_scene(dir, 0.475);
  write(dir / "prof" / "shifted.csv", cylinder_tread(0.475, 0.001));  // y from 1 mm to 41 mm
  write(dir / "s.toml", "base = \"prof/tread.toml\"\nrun = [\"analytic\"]\n[axes]\n"
                        "\"wheel.profile\" = [\"prof/tread.csv\", \"prof/shifted.csv\"]\n\"wheel.speed\" = [30.0, 50.0]\n");
  ASSERT_EQ(sweep(dir / "s.toml", dir / "out").exit_code, 0);
  const CsvTable t = read_csv(dir / "out" / "results.csv");
  ASSERT_EQ(t.size(), 5u);
  for (std::size_t r = 1; r <= 2; ++r) EXPECT_EQ(t[r][column(t, "verdict")], "ok") << t[r][column(t, "message")];
  for (std::size_t r = 3; r <= 4; ++r) {
    const std::string& message = t[r][column(t, "message")];
    EXPECT_EQ(t[r][column(t, "verdict")], "rejected");
    EXPECT_NE(message.find("key 'wheel.profile'"), std::string::npos) << message;
    EXPECT_NE(message.find("shifted.csv"), std::string::npos) << message;
    EXPECT_NE(message.find("y = 0"), std::string::npos) << message;
  }
}

// Item 13: [set] fixes a key for every case, as --set on the base scene
// (the workaround was a one-value axis). A key both fixed and swept is
// refused naming both; [set] is part of the fingerprint.
TEST(SweepSet, FixesAKeyForEveryCase) {
  const fs::path dir = temporary_folder("sweep_set");
  const fs::path s = dir / "s.toml";
  write(s, "base = \"" + testing_support::default_scene_path() + "\"\nrun = [\"analytic\"]\n"
           "[set]\n\"wheel.speed\" = 30.0\njoint.beta = 0.02\n[axes]\n\"wheel.y\" = [0.0, 0.015]\n");
  ASSERT_EQ(sweep(s, dir / "out").exit_code, 0);
  const CsvTable t = read_csv(dir / "out" / "results.csv");
  ASSERT_EQ(t.size(), 3u);
  // The CLI with the same --set: the row's numbers.
  for (const std::size_t r : {1u, 2u}) {
    const std::string y = r == 1 ? "0" : "0.015";
    const RunResult cli = run_railjoint("analytic " + testing_support::default_scene_path() +
                                        " --set wheel.speed=30 --set joint.beta=0.02 --set wheel.y=" + y + " --json");
    ASSERT_EQ(cli.exit_code, 0) << cli.output;
    EXPECT_EQ(std::stod(t[r][column(t, "analytic.exact_Ns")]),
              nlohmann::json::parse(cli.output).at("exact_Ns").get<double>());
  }
  // Scenario 1 on the centre line, exact with v held: 2 M v tan(beta/2) =
  // 2 x 750 kg x 30 m/s x tan(0.01) = 450.015 N s (docs: the three forms).
  EXPECT_NEAR(std::stod(t[1][column(t, "analytic.exact_Ns")]), 2.0 * 750.0 * 30.0 * std::tan(0.01), 1e-9);

  // Changed [set]: another sweep.
  write(s, "base = \"" + testing_support::default_scene_path() + "\"\nrun = [\"analytic\"]\n"
           "[set]\n\"wheel.speed\" = 40.0\njoint.beta = 0.02\n[axes]\n\"wheel.y\" = [0.0, 0.015]\n");
  const RunResult changed = sweep(s, dir / "out");
  EXPECT_EQ(changed.exit_code, 2);
  EXPECT_NE(changed.output.find("holds the results of another sweep"), std::string::npos) << changed.output;
}

TEST(SweepSet, AKeyBothFixedAndSweptIsRefusedNamingBoth) {
  const fs::path dir = temporary_folder("sweep_set_bad");
  const std::string base = "base = \"" + testing_support::default_scene_path() + "\"\nrun = [\"analytic\"]\n";
  write(dir / "both.toml", base + "[set]\n\"wheel.y\" = 0.01\n[axes]\n\"wheel.y\" = [0.0, 0.015]\n");
  const RunResult both = sweep(dir / "both.toml", dir / "out");
  EXPECT_EQ(both.exit_code, 2);
  EXPECT_NE(both.output.find("key 'set.wheel.y': is also an axis (axes.wheel.y)"), std::string::npos) << both.output;
  write(dir / "typo.toml", base + "[set]\n\"wheel.sped\" = 30.0\n[axes]\n\"wheel.y\" = [0.0]\n");
  const RunResult typo = sweep(dir / "typo.toml", dir / "out2");
  EXPECT_EQ(typo.exit_code, 2);
  EXPECT_NE(typo.output.find("key 'set.wheel.sped': is not a scene key"), std::string::npos) << typo.output;
  write(dir / "list.toml", base + "[set]\n\"wheel.y\" = [0.0, 0.01]\n[axes]\n\"wheel.speed\" = [30.0]\n");
  const RunResult list = sweep(dir / "list.toml", dir / "out3");
  EXPECT_EQ(list.exit_code, 2);
  EXPECT_NE(list.output.find("key 'set.wheel.y': takes one value"), std::string::npos) << list.output;
}

// A [set] value out of its range rejected every case and the sweep exited 0
// ("verdicts: ok 0 ... rejected 2", rc 0): a sweep that computed nothing
// now exits 2 with the first case's reason. Its rows are still written.
TEST(SweepSet, AValueThatRejectsEveryCaseIsTheSweepsError) {
  const fs::path dir = temporary_folder("sweep_set_range");
  const std::string base = "base = \"" + testing_support::default_scene_path() + "\"\nrun = [\"analytic\"]\n";
  write(dir / "fast.toml", base + "[set]\n\"wheel.speed\" = 5000.0\n[axes]\n\"wheel.y\" = [0.0, 0.01]\n");
  const RunResult fast = sweep(dir / "fast.toml", dir / "out");
  EXPECT_EQ(fast.exit_code, 2) << fast.output;
  EXPECT_NE(fast.output.find("every case run (2) was rejected, the first one's scene"), std::string::npos) << fast.output;
  EXPECT_NE(fast.output.find("key 'wheel.speed': must be in [0.1, 1000] m/s, got 5000"), std::string::npos)
      << fast.output;
  EXPECT_EQ(read_csv(dir / "out" / "results.csv").size(), 3u);
  // One case of two refused is a sweep with a result: exit 0, as before;
  // so is one whose every case a model refuses (pressure needs a gap) while
  // the others fill their columns.
  write(dir / "model.toml", "base = \"" + testing_support::default_scene_path() +
                                "\"\nrun = [\"analytic\", \"pressure\"]\n[axes]\n\"wheel.speed\" = [30.0]\n");
  EXPECT_EQ(sweep(dir / "model.toml", dir / "out_model").exit_code, 0);
  write(dir / "some.toml", base + "[axes]\n\"wheel.speed\" = [30.0, 5000.0]\n");
  EXPECT_EQ(sweep(dir / "some.toml", dir / "out_some").exit_code, 0);
}

}  // namespace
}  // namespace railjoint
