// `railjoint sweep` as a user runs it: one-line errors with exit code 2,
// progress lines in a log, and the same rows from `mpirun -np 3` as from
// one thread.

#include <cstdlib>
#include <filesystem>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/run_cli.h"
#include "tests/sweeps/sweep_test_support.h"

namespace {

namespace fs = std::filesystem;
using railjoint::testing_support::read_csv;
using railjoint::testing_support::RunResult;
using railjoint::testing_support::run_railjoint;
using railjoint::testing_support::run_shell;
using railjoint::testing_support::temporary_folder;
using railjoint::testing_support::without_wall_time;
using railjoint::testing_support::write_sweep;
using railjoint::testing_support::column;

const char* kSweep = R"(run = ["analytic", "simulate"]
[axes]
"joint.theta_deg" = [30.0, 60.0]
"wheel.y" = { from = -0.015, to = 0.025, count = 5 }
"joint.beta" = { from = 0.01, to = 0.05, scale = "log" }
[sample]
count = 3
seed = 11
)";

TEST(SweepCli, BadSweepFileIsOneLineAndExitCode2) {
  const fs::path dir = temporary_folder("sweep_cli_bad");
  const std::string sweep = write_sweep(dir, "bad.toml", "run = [\"analytic\"]\n[axes]\n\"wheel.y\" = { from = 0.0, to = 0.01 }\n");
  const RunResult r = run_railjoint("sweep " + sweep + " --out " + (dir / "out").string());
  std::cout << r.output;
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.output, "railjoint: error: " + sweep +
                          ": key 'axes.wheel.y.count': is missing: an even or log range needs count = number of values "
                          "(or a [sample] section to sample the range)\n");
  EXPECT_EQ(run_railjoint("sweep " + sweep + " --out x --shard 4/3").exit_code, 2);
}

TEST(SweepCli, RunsAndReportsProgressInALog) {
  const fs::path dir = temporary_folder("sweep_cli_run");
  const RunResult r = run_railjoint("sweep " + write_sweep(dir, "s.toml", kSweep) + " --out " + (dir / "out").string());
  std::cout << r.output;
  ASSERT_EQ(r.exit_code, 0);
  // stderr is a pipe here: plain progress lines, no bar redrawn in place.
  EXPECT_NE(r.output.find("s: 30/30 cases (100.0 %)"), std::string::npos);
  EXPECT_EQ(r.output.find('\r'), std::string::npos);
  EXPECT_NE(r.output.find("sweep s: 30 cases; 0 had a row already; ran 30"), std::string::npos);
  EXPECT_EQ(read_csv(dir / "out" / "results.csv").size(), 31u);
}

TEST(SweepCli, MpiRanksGiveTheRowsOfOneThread) {
  if (!RAILJOINT_HAVE_MPI) GTEST_SKIP() << "built without MPI (RAILJOINT_WITH_MPI off or libopenmpi-dev missing)";
  if (run_shell("command -v mpirun").exit_code != 0) GTEST_SKIP() << "no mpirun on PATH (openmpi-bin)";
  const fs::path dir = temporary_folder("sweep_cli_mpi");
  const std::string sweep = write_sweep(dir, "s.toml", kSweep);
  const RunResult one = run_railjoint("sweep " + sweep + " --jobs 1 --out " + (dir / "one").string());
  ASSERT_EQ(one.exit_code, 0) << one.output;
  // Open MPI refuses to run as root without these (CI runs as root).
  const std::string mpirun = "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 mpirun --oversubscribe -np 3 ";
  const RunResult mpi = run_shell(mpirun + RAILJOINT_EXE + " sweep " + sweep + " --out " + (dir / "mpi").string());
  std::cout << mpi.output;
  ASSERT_EQ(mpi.exit_code, 0) << mpi.output;
  EXPECT_NE(mpi.output.find("(3 ranks)"), std::string::npos);
  EXPECT_NE(mpi.output.find("on 3 workers"), std::string::npos);
  EXPECT_EQ(without_wall_time(read_csv(dir / "mpi" / "results.csv")),
            without_wall_time(read_csv(dir / "one" / "results.csv")));
  // A bad sweep under mpirun: rank 0's one line, every rank ends.
  const RunResult bad = run_shell(mpirun + RAILJOINT_EXE + " sweep " + (dir / "missing.toml").string() + " --out " +
                                  (dir / "bad").string());
  std::cout << bad.output;
  EXPECT_NE(bad.exit_code, 0);
  EXPECT_NE(bad.output.find("railjoint: error: " + (dir / "missing.toml").string() + ": no such sweep file"),
            std::string::npos);
}

// Issue 41, item 1: the sweep's force columns, rail seat and ballast
// included, are the numbers `simulate --json` gives for the same case, to
// the digits both print (each the shortest round trip of the same double).
// On the discrete track, which records no support forces, both are empty.
TEST(SweepCli, ForceColumnsAreTheSimulateJsonOfTheSameCase) {
  const fs::path dir = temporary_folder("sweep_cli_forces");
  const std::string sweep = write_sweep(dir, "forces.toml", R"(run = ["forces"]
[axes]
"sim.mode" = ["inertial"]
"contact.law" = ["hertz"]
"track.model" = ["lumped", "discrete"]
"wheel.speed" = [30.0]
)");
  const RunResult r = run_railjoint("sweep " + sweep + " --out " + (dir / "out").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto t = read_csv(dir / "out" / "results.csv");
  ASSERT_EQ(t.size(), 3u);
  const std::vector<std::pair<std::string, std::string>> columns = {
      {"forces.static_N", "static_N"},
      {"forces.p1_N", "p1_N"},
      {"forces.p2_N", "p2_N"},
      {"forces.p2_rail_seat_N", "p2_rail_seat_N"},
      {"forces.rail_seat_peak_N", "rail_seat_peak_N"},
      {"forces.ballast_peak_N", "ballast_peak_N"}};
  for (std::size_t row = 1; row < t.size(); ++row) {
    const std::string model = t[row][column(t, "track.model")];
    const RunResult s = run_railjoint("simulate " + std::string(RAILJOINT_SOURCE_DIR) +
                                      "/scenes/default.toml --set sim.mode=inertial --set contact.law=hertz "
                                      "--set track.model=" + model + " --set wheel.speed=30.0 --json");
    ASSERT_EQ(s.exit_code, 0) << s.output;
    const nlohmann::json forces = nlohmann::json::parse(s.output).at("sim").at("forces");
    for (const auto& [csv_name, json_name] : columns) {
      const std::string cell = t[row][column(t, csv_name)];
      std::cout << model << " " << csv_name << ": sweep '" << cell << "', simulate " << forces.at(json_name) << "\n";
      if (forces.at(json_name).is_null()) {
        EXPECT_TRUE(cell.empty()) << model << " " << csv_name;
        EXPECT_EQ(model, "discrete") << json_name << " is null on the lumped track";
      } else {
        ASSERT_FALSE(cell.empty()) << model << " " << csv_name;
        EXPECT_EQ(std::stod(cell), forces.at(json_name).get<double>()) << model << " " << csv_name;
      }
    }
  }
}

// A simulating case's rails are derived from the predictions its run is
// built with, after the prediction, as `simulate` and `analytic` derive them:
// the sweep's row is then the commands' numbers to the last bit. The case
// (an inclined joint, a wheel near the head's edge, inertial) is one where
// the prediction moves at round-off with the rail length it is made on:
// when the sweep derived the simulated rails before predicting, its
// analytic.exact_Ns read 773.1089540401717 against the commands'
// 773.1089540401897 (2.3e-14 of it), and simulate.jump_Ns differed too.
TEST(SweepCli, ASimulatingCaseIsTheCommandsNumbersToTheLastBit) {
  const fs::path dir = temporary_folder("sweep_cli_rails");
  const std::string values =
      "--set joint.beta=0.005919645769738039 --set joint.theta_deg=39.9195456959729 "
      "--set wheel.y=0.014264912277532928 --set sim.mode=inertial";
  const std::string sweep = write_sweep(dir, "rails.toml", R"(run = ["analytic", "simulate"]
[axes]
"joint.beta" = [0.005919645769738039]
"joint.theta_deg" = [39.9195456959729]
"wheel.y" = [0.014264912277532928]
"sim.mode" = ["inertial"]
)");
  const RunResult r = run_railjoint("sweep " + sweep + " --out " + (dir / "out").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto t = read_csv(dir / "out" / "results.csv");
  ASSERT_EQ(t.size(), 2u);
  const std::string scene = std::string(RAILJOINT_SOURCE_DIR) + "/scenes/default.toml ";
  const RunResult s = run_railjoint("simulate " + scene + values + " --json");
  ASSERT_EQ(s.exit_code, 0) << s.output;
  const nlohmann::json simulated = nlohmann::json::parse(s.output);
  EXPECT_EQ(std::stod(t[1][column(t, "analytic.exact_Ns")]), simulated.at("analytic").at("exact_Ns").get<double>());
  EXPECT_EQ(std::stod(t[1][column(t, "analytic.x_A_m")]), simulated.at("analytic").at("x_A_m").get<double>());
  EXPECT_EQ(std::stod(t[1][column(t, "simulate.jump_Ns")]), simulated.at("sim").at("impulse_Ns").get<double>());
}

}  // namespace
