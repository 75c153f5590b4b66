#pragma once
// Peak forces against speed (`railjoint study forces`): P1 and P2 of force
// runs (sim/elastic_crossing_run.h) beside Jenkins's, for a square joint and
// an inclined one in contact scenario 1 and 2, each a set of --set
// overrides of one base scene (a force scene: sim.mode = "inertial",
// contact.law = "hertz"), so `railjoint simulate BASE --set ...` reproduces a
// row. Also the force histories at one speed, for the familiar double peak.

#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "scenes/report/force_run_numbers.h"
#include "scenes/scene.h"
#include "scenes/studies/study_table.h"
#include "sim/simulation_result.h"
#include "support/case_pool.h"

namespace railjoint {

struct ForceStudyCase {
  std::string joint;  ///< "square", "scenario 1", "scenario 2"
  std::vector<std::string> overrides;  ///< --set assignments on the base scene
  double speed_m_per_s = 0.0;
};

/// A force run of a base scene with --set overrides: its numbers
/// (force_run_numbers.h) when it ran, else why not.
struct ForceRun : ForceRunNumbers {
  bool ran = false;
  std::string error;      ///< why it did not run (the scene or the model refused it)
  std::string overrides;  ///< the --set assignments that reproduce it, space-separated
};

/// Throws InputError unless the scene is a force run (sim.mode = "inertial", contact.law = "hertz").
void check_force_scene(const Scene& scene);

/// Loads and runs a force scene (sim.mode = "inertial", contact.law =
/// "hertz"); `read`, when given, also reads the result while it is there.
ForceRun run_force_scene(const std::string& base_scene, const std::vector<std::string>& overrides,
                         const std::function<void(const SimulationResult&)>& read = {});

struct ForceStudyOutcome : ForceRun {
  ForceStudyCase study_case;
  /// The contact force history (time [s], force [N], low-passed force [N]) when asked for.
  std::vector<double> time_s, force_N, force_lowpass_N;
};

/// The study's cases: 3 joints x speeds 10-80 m/s (quick: 30 and 50 m/s).
/// Scenario 2 puts the disc at y_w = 10 mm on a 45 deg cut (y_t = 7.1 mm at
/// beta 0.03), scenario 1 on its centre line; the square joint is 90 deg.
std::vector<ForceStudyCase> force_study_cases(bool quick);

/// Runs every case on the base scene (each a force run; histories kept for
/// `history_speed_m_per_s`), in parallel; outcomes in the cases' order.
std::vector<ForceStudyOutcome> run_force_study(const std::string& base_scene, const std::vector<ForceStudyCase>& cases,
                                               double history_speed_m_per_s, const ParallelRuns& parallel = {});

/// The CSV (N, s) and its Markdown (kN): P1 and P2 simulated and Jenkins's, their ratio.
StudyTable force_study_table(const std::vector<ForceStudyOutcome>& outcomes);
/// joint,speed_m_per_s,t_ms,force_kN,force_lowpass_kN for the outcomes with a history.
void write_force_histories_csv(const std::vector<ForceStudyOutcome>& outcomes, std::ostream& out);

}  // namespace railjoint
