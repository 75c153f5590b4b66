// The sweep runner in-process: a bad case is a row, the rows do not depend
// on the number of threads, shards add up to the whole sweep, a rerun
// resumes (and runs only what is missing), a changed sweep file is refused.

#include "scenes/sweeps/sweep_runner.h"

#include <cmath>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "scenes/scene_file.h"
#include "scenes/sweeps/case_models.h"
#include "sim/simulate_crossing.h"
#include "support/input_error.h"
#include "tests/sweeps/sweep_test_support.h"

namespace railjoint {
namespace {

namespace fs = std::filesystem;
using testing_support::column;
using testing_support::CsvTable;
using testing_support::read_csv;
using testing_support::temporary_folder;
using testing_support::without_wall_time;
using testing_support::write_sweep;

SweepSummary run(const std::string& sweep_path, const fs::path& out, int jobs, Shard shard = {}) {
  SweepRunOptions options;
  options.out_dir = out;
  options.jobs = jobs;
  options.shard = shard;
  options.progress = false;
  const SweepSummary summary = run_sweep(load_sweep_file(sweep_path, case_model_names()), options);
  std::cout << sweep_summary_text(summary);
  return summary;
}

// Square joint (theta = 90 deg) against the thesis's scenario-1 jump, exact
// with v held: 2 M v tan(beta/2) (models/DESIGN.md "Three forms of every
// analytic impulse"), M = 750 kg, v = 50 m/s from scenes/default.toml. Its y_w = 0.03 m is off the 20 mm rail head: rejected.
const char* kSquareSweep = R"(run = ["analytic", "simulate"]
[axes]
"joint.theta_deg" = [90.0]
"joint.beta" = [0.01, 0.03]
"wheel.y" = [0.0, 0.01, 0.03]
)";

TEST(SweepRunner, EveryCaseIsARowAndABadCaseSaysWhy) {
  const fs::path dir = temporary_folder("sweep_rows");
  const SweepSummary s = run(write_sweep(dir, "square.toml", kSquareSweep), dir / "out", 2);
  EXPECT_EQ(s.cases, 6u);
  EXPECT_EQ(s.ran, 6u);
  const CsvTable t = read_csv(dir / "out" / "results.csv");
  ASSERT_EQ(t.size(), 7u);
  const std::size_t verdict = column(t, "verdict"), message = column(t, "message");
  const std::size_t exact = column(t, "analytic.exact_Ns"), jump = column(t, "simulate.jump_Ns");
  for (std::size_t r = 1; r < t.size(); ++r) {
    EXPECT_EQ(t[r][0], std::to_string(r - 1)) << "rows in case order";
    const double beta = std::stod(t[r][column(t, "joint.beta")]);
    const double y = std::stod(t[r][column(t, "wheel.y")]);
    if (y > 0.02) {
      EXPECT_EQ(t[r][verdict], "rejected");
      EXPECT_NE(t[r][message].find("key 'wheel.y'"), std::string::npos) << t[r][message];
      EXPECT_EQ(t[r][exact], "");
      continue;
    }
    EXPECT_EQ(t[r][verdict], "ok") << t[r][message];
    const double expected = 2.0 * 750.0 * 50.0 * std::tan(beta / 2.0);
    std::cout << "beta " << beta << " y " << y << ": exact " << t[r][exact] << " sim " << t[r][jump] << " expected "
              << expected << "\n";
    // The analytic exact form is this formula to round-off; scenario 1 is
    // simulated to round-off too (tests/sim: rolling plane to plane).
    EXPECT_NEAR(std::stod(t[r][exact]) / expected, 1.0, 1e-12);
    EXPECT_NEAR(std::stod(t[r][jump]) / expected, 1.0, 1e-9);
  }
}

// A mixed sweep: scenario 1 and 2, a step, a rejected case, cheap and dear cases.
const char* kMixedSweep = R"(run = ["analytic", "simulate"]
[axes]
"joint.theta_deg" = [30.0, 60.0]
"wheel.y" = { from = -0.015, to = 0.025, count = 5 }
"wheel.speed" = [20.0, 50.0]
)";

TEST(SweepRunner, RowsIdenticalWhateverTheThreads) {
  const fs::path dir = temporary_folder("sweep_jobs");
  const std::string sweep = write_sweep(dir, "mixed.toml", kMixedSweep);
  run(sweep, dir / "one", 1);
  run(sweep, dir / "two", 2);
  run(sweep, dir / "five", 5);
  const CsvTable one = without_wall_time(read_csv(dir / "one" / "results.csv"));
  ASSERT_EQ(one.size(), 21u);
  EXPECT_EQ(one, without_wall_time(read_csv(dir / "two" / "results.csv")));
  EXPECT_EQ(one, without_wall_time(read_csv(dir / "five" / "results.csv")));
}

TEST(SweepRunner, ShardsAddUpToTheWholeSweepAndMerge) {
  const fs::path dir = temporary_folder("sweep_shards");
  const std::string sweep = write_sweep(dir, "mixed.toml", kMixedSweep);
  run(sweep, dir / "whole", 2);
  std::uint64_t ran = 0;
  CsvTable united;
  for (std::uint64_t i = 1; i <= 3; ++i) {
    ran += run(sweep, dir / "shards", 1, Shard{i, 3}).ran;
    const CsvTable part = read_csv(dir / "shards" / ("results.shard-" + std::to_string(i) + "-of-3.csv"));
    for (std::size_t r = 1; r < part.size(); ++r) {
      EXPECT_EQ(std::stoull(part[r][0]) % 3, i - 1) << "shard i holds cases i-1, i-1+N, ...";
      united.push_back(part[r]);
    }
  }
  EXPECT_EQ(ran, 20u);
  std::sort(united.begin(), united.end(), [](const auto& a, const auto& b) { return std::stoull(a[0]) < std::stoull(b[0]); });
  CsvTable whole = read_csv(dir / "whole" / "results.csv");
  united.insert(united.begin(), whole.front());
  EXPECT_EQ(without_wall_time(united), without_wall_time(whole));
  // A plain run on the shards' folder merges them and runs nothing.
  const SweepSummary merge = run(sweep, dir / "shards", 2);
  EXPECT_EQ(merge.ran, 0u);
  EXPECT_EQ(merge.imported, 20u);
  EXPECT_EQ(without_wall_time(read_csv(dir / "shards" / "results.csv")), without_wall_time(whole));
}

TEST(SweepRunner, ResumeRunsOnlyTheMissingCases) {
  const fs::path dir = temporary_folder("sweep_resume");
  const std::string sweep = write_sweep(dir, "mixed.toml", kMixedSweep);
  const SweepSummary first = run(sweep, dir / "out", 2);
  EXPECT_EQ(first.ran, 20u);
  const CsvTable complete = without_wall_time(read_csv(dir / "out" / "results.csv"));
  EXPECT_EQ(run(sweep, dir / "out", 2).ran, 0u) << "a finished sweep runs nothing";

  // As a kill leaves it: the header, 8 rows, and half of the 9th row.
  const fs::path csv = dir / "out" / "results.csv";
  std::string text;
  {
    std::ifstream in(csv);
    std::string line;
    for (int i = 0; i < 9 && std::getline(in, line); ++i) text += line + "\n";
    std::getline(in, line);
    text += line.substr(0, line.size() / 2);
  }
  std::ofstream(csv, std::ios::trunc) << text;
  const SweepSummary resumed = run(sweep, dir / "out", 2);
  EXPECT_EQ(resumed.finished_before, 8u);
  EXPECT_EQ(resumed.ran, 12u) << "the cut row's case runs again, the 8 whole rows do not";
  EXPECT_EQ(without_wall_time(read_csv(csv)), complete);
}

// The local model is one more group of columns. A square cut (theta = 90
// deg) under the default ellipse patch, full axes a = 16 mm along x and
// b = 12 mm (scenes/contact_patch_section.h), over a gap g normal to the cut:
// the bearing area is least with the patch centred on the gap, where the
// strip |x| <= g/2 of the ellipse (semi-axes A = a/2, B = b/2) is lost:
//   strip = 2 A B (t sqrt(1 - t^2) + asin t),  t = g / a,
// so the largest pressure is P0 A0 / (A0 - strip) with A0 = pi A B.
TEST(SweepRunner, PressureModelMatchesTheStripOfTheEllipse) {
  const fs::path dir = temporary_folder("sweep_pressure");
  const std::string sweep = write_sweep(dir, "pressure.toml",
                                        "run = [\"pressure\"]\n[axes]\n\"joint.theta_deg\" = [90.0]\n"
                                        "\"joint.gap\" = [0.0, 0.002, 0.005, 0.01]\n");
  run(sweep, dir / "out", 2);
  const CsvTable t = read_csv(dir / "out" / "results.csv");
  ASSERT_EQ(t.size(), 5u);
  EXPECT_EQ(t[1][column(t, "verdict")], "rejected") << "no gap: the local model has nothing to show";
  EXPECT_NE(t[1][column(t, "message")].find("key 'joint.gap'"), std::string::npos);
  const double A = 0.008, B = 0.006, A0 = M_PI * A * B;
  for (std::size_t r = 2; r < t.size(); ++r) {
    const double g = std::stod(t[r][column(t, "joint.gap")]);
    const double u = g / (2.0 * A);
    const double strip = 2.0 * A * B * (u * std::sqrt(1.0 - u * u) + std::asin(u));
    const double area = std::stod(t[r][column(t, "pressure.min_active_area_m2")]);
    const double relative = std::stod(t[r][column(t, "pressure.max_relative_pressure")]);
    std::cout << "gap " << g << ": least area " << area << " (strip formula " << A0 - strip << ", ratio - 1 = "
              << area / (A0 - strip) - 1.0 << "), P/P0 " << relative << " (" << A0 / (A0 - strip) << ")\n";
    // The model's area is exact (edge sums) and its maximum refined: seen
    // 0 to 3e-14 relative; 1e-12 leaves room for the refinement's round-off.
    EXPECT_NEAR(area / (A0 - strip), 1.0, 1e-12);
    EXPECT_NEAR(relative / (A0 / (A0 - strip)), 1.0, 1e-12);
  }
}

// A model names its columns apart from the function that writes its cells
// (case_model.h): a cell added to one and not the other would shift every
// later cell under another column's name. Each model, on a case it runs
// (verdict ok: a refused model's cells are blanks counted from its names),
// writes one cell per column it names (a 5 mm gap: the local model needs one).
TEST(SweepRunner, EachModelWritesOneCellPerColumnItNames) {
  const std::string scenes = std::string(RAILJOINT_SOURCE_DIR) + "/scenes/";
  const std::vector<std::pair<std::string, std::string>> uses = {
      {"analytic", "default.toml"}, {"simulate", "default.toml"},
      {"pressure", "default.toml"}, {"forces", "forces/lumped_track.toml"}};
  ASSERT_EQ(uses.size(), case_model_names().size()) << "every registered model";
  for (const auto& [model, base] : uses) {
    const SweepFile sweep = parse_sweep_file("base = \"" + scenes + base + "\"\nrun = [\"" + model +
                                                 "\"]\n[axes]\n\"joint.gap\" = [0.005]\n",
                                             "cells.toml", std::nullopt, case_model_names());
    const CaseEvaluator evaluator(sweep, case_models(sweep.models));
    CaseScratch scratch;
    CsvRow row;
    const CaseVerdict verdict = evaluator.append_row(0, scratch, row);
    const std::string line = row.str().substr(0, row.str().size() - 1);  // without its newline
    std::cout << model << ": " << evaluator.header() << "\n  " << line << "\n";
    EXPECT_EQ(verdict, CaseVerdict::ok) << line;
    EXPECT_EQ(testing_support::split_csv_line(line).size(), testing_support::split_csv_line(evaluator.header()).size())
        << model;
  }
}

TEST(SweepRunner, ChangedSweepFileOrBaseSceneIsRefused) {
  const fs::path dir = temporary_folder("sweep_changed");
  const std::string sweep = write_sweep(dir, "square.toml", kSquareSweep);
  run(sweep, dir / "out", 1);
  std::ofstream(sweep, std::ios::app) << "# a comment changes the file too\n";
  try {
    run(sweep, dir / "out", 1);
    FAIL() << "a changed sweep file must be refused";
  } catch (const InputError& error) {
    std::cout << error.what() << "\n";
    EXPECT_EQ(error.key(), "--out");
    EXPECT_NE(std::string(error.what()).find("changed since"), std::string::npos);
  }
  EXPECT_EQ(run(sweep, dir / "fresh", 1).ran, 6u) << "another --out starts afresh";
}

// Issue 29, items 1-2: one rule for the derived rail length. A sweep case
// that gives no joint.length gets the rails `simulate` derives for it, so its
// row is the simulate run: the fast inertial scenario-2 strike (its flight
// needs 2.41 m of rail) and a 1 deg cut (the cut alone reaches 1.15 m along
// the track across the 20 mm head) used to be rejected rows ("joint.length
// must be >= ..."), while `simulate` ran them (or refused the length it had
// derived itself, on the 1 deg cut).
TEST(SweepRunner, ARowIsTheSimulateRunOfItsCase) {
  const fs::path dir = temporary_folder("sweep_derived_length");
  const std::string sweep = write_sweep(dir, "derived.toml", R"(run = ["analytic", "simulate"]
[axes]
"sim.mode" = ["kinematic", "inertial"]
"joint.theta_deg" = [1.0, 45.0]
"wheel.y" = [0.015]
)");
  run(sweep, dir / "out", 2);
  const CsvTable t = read_csv(dir / "out" / "results.csv");
  ASSERT_EQ(t.size(), 5u);
  const std::string base = std::string(RAILJOINT_SOURCE_DIR) + "/scenes/default.toml";
  for (std::size_t r = 1; r < t.size(); ++r) {
    const std::string mode = t[r][column(t, "sim.mode")];
    const std::string theta = t[r][column(t, "joint.theta_deg")];
    const Scene scene = load_scene(base, {"sim.mode=" + mode, "joint.theta_deg=" + theta, "wheel.y=0.015"});
    const SimulationResult simulated = simulate_crossing(scene.joint, scene.wheel, scene.sim);
    std::cout << mode << " theta " << theta << ": " << t[r][column(t, "verdict")] << " " << t[r][column(t, "message")]
              << " jump " << t[r][column(t, "simulate.jump_Ns")] << ", simulate " << simulated.impulse_Ns()
              << " N s on " << scene.joint.length_m << " m of rail\n";
    EXPECT_EQ(t[r][column(t, "verdict")], "ok") << t[r][column(t, "message")];
    ASSERT_FALSE(t[r][column(t, "simulate.jump_Ns")].empty());
    // The same run: equal to the CSV's round-trip digits.
    EXPECT_NEAR(std::stod(t[r][column(t, "simulate.jump_Ns")]), simulated.impulse_Ns(), 1e-12 * simulated.impulse_Ns());
  }
}

// A force run's P1 and P2 times are on every output's one clock (t = 0 when
// the centre passes the predicted impact, scenes/report/outputs.md): the
// sweep's row counted them from the run's start, 1 ms apart from simulate's.
TEST(SweepRunner, ForceTimesAreOnTheOutputsClock) {
  const fs::path dir = temporary_folder("sweep_force_times");
  const std::string sweep = write_sweep(dir, "forces.toml", R"(run = ["forces"]
[axes]
"sim.mode" = ["inertial"]
"contact.law" = ["hertz"]
"wheel.speed" = [30.0]
)");
  run(sweep, dir / "out", 1);
  const CsvTable t = read_csv(dir / "out" / "results.csv");
  ASSERT_EQ(t.size(), 2u);
  ASSERT_EQ(t[1][column(t, "verdict")], "ok") << t[1][column(t, "message")];
  const Scene scene = load_scene(std::string(RAILJOINT_SOURCE_DIR) + "/scenes/default.toml",
                                 {"sim.mode=inertial", "contact.law=hertz", "wheel.speed=30.0"});
  const SimulationResult r = simulate_crossing(scene.joint, scene.wheel, scene.sim);
  // The run starts at the approach distance before the predicted impact:
  // at 30 m/s its clock is shifted by (impact x - start x) / v from the outputs'.
  const double start_to_impact_s = (r.prediction().impact_wheel_x_m - r.trajectory.samples.front().centre_m.x()) / 30.0;
  const double p1_run_s = r.inertial()->forces->p1_time_s;
  EXPECT_NEAR(std::stod(t[1][column(t, "forces.p1_time_s")]), p1_run_s - start_to_impact_s, 1e-9);
}

}  // namespace
}  // namespace railjoint
