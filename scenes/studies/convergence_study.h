#pragma once
// Error against run time: one scene simulated over a ladder of numerical
// settings (fixed steps, adaptive refinement, solver iterations), each point
// timed as the median of several runs and compared with the exact analytic
// jump of the governing slice as simulated. Answers "which settings are
// worth their cost" and "are the defaults among them".

#include <optional>
#include <string>
#include <vector>

#include "models/impact_prediction.h"
#include "scenes/scene.h"
#include "scenes/studies/pareto_front.h"
#include "scenes/studies/study_table.h"
#include "sim/sim_settings.h"
#include "support/case_pool.h"

namespace railjoint {

/// One point of the ladder.
struct ConvergenceSetting {
  /// Curves it belongs to ("fixed", "adaptive", "iterations", "default"); a
  /// setting on two curves (the default step with 10 iterations) is run once.
  std::vector<std::string> families;
  std::string label;  ///< e.g. "dt 1e-05 s", "1e-04 -> 1e-06 s", "30 iterations"
  SimSettings settings;
  bool is_default = false;  ///< the scene's own [sim] settings
};

/// The ladder on top of `base` (the scene's settings):
///  - fixed: time_step = refined_time_step = 1e-3, 3e-4, ..., 1e-6 s (no refinement);
///  - adaptive: time_step 1e-4 s refined to 1e-5, 3e-6, 1e-6, 3e-7, 1e-7 s;
///  - iterations: 1, 4, 10, 30, 100 solver iterations at the base steps;
///  - solved from: contacts solved from a gap of 1e-8 .. 1e-12 m;
///  - narrow phase: Bullet's GJK/EPA with the settings it was tuned with;
///  - default: the base itself if it is none of the above (else that point is flagged is_default).
/// Settings equal in (time_step, refined_time_step, solver_iterations) are merged.
std::vector<ConvergenceSetting> convergence_ladder(const SimSettings& base);

/// The reduced ladder of the tests: the listed refined steps at a 1e-4 s coarse step.
std::vector<ConvergenceSetting> refinement_ladder(const SimSettings& base, const std::vector<double>& refined_steps_s);

struct ConvergencePoint {
  ConvergenceSetting setting;
  bool impact_found = false;
  /// "" if an impact was measured; else "no impact", "rejected: <key>: <message>"
  /// for settings the sim refuses (InputError), or another exception's message.
  std::string failure;
  double impulse_Ns = 0.0;
  /// |simulated - exact| / exact; NaN when no impact was found or the run failed.
  double abs_relative_error = 0.0;
  double median_wall_s = 0.0;      ///< median over the repeats of the simulate_crossing call [s]
  /// Median CPU time of this thread over the call [s]: what the front ranks
  /// by, since on a shared machine the wall time also counts other processes.
  double median_cpu_s = 0.0;
  double median_sim_wall_s = 0.0;  ///< median of SimulationResult::wall_seconds (world build + stepping) [s]
  /// max - min of the measured jump over the repeats [N s]; 0 = deterministic.
  double repeat_spread_Ns = 0.0;
  int steps = 0;
  int refined_steps = 0;
  double max_penetration_m = 0.0;
  /// Gain a dominating setting of the ladder offers (pareto_front.h): 1 = on the front.
  double domination_factor = 1.0;
};

struct ConvergenceStudy {
  std::string scene_name;
  std::string scene_file;
  int repeats = 0;
  int jobs = 1;  ///< runs at a time, each on one thread
  ImpulseForms forms;  ///< the governing slice as simulated (the same for every point)
  double thesis_vs_exact = 0.0;       ///< |thesis - exact| / exact
  double small_angle_vs_exact = 0.0;  ///< |small_angle - exact| / exact
  std::vector<ConvergencePoint> points;
  std::vector<std::size_t> front;  ///< indices into points, by increasing wall time
  /// Where the default point stands (factor 1 = on the front, <= 1.1 within
  /// 10 % of it); factor NaN if the default found no impact.
  Domination default_domination;
  std::optional<std::size_t> default_index;  ///< empty: the default is not in the ladder
};

/// Runs every setting `repeats` times (>= 1), round robin over the ladder
/// (the repeats of one setting are spread over the whole study), on
/// parallel.jobs threads: each run's wall time is its own thread's, while
/// the machine's other cores run other runs. A run that throws (e.g. an
/// InputError for settings the sim rejects) becomes a point with the
/// message as failure and NaN error and times; nothing is made up.
ConvergenceStudy run_convergence_study(const Scene& scene, const std::vector<ConvergenceSetting>& ladder, int repeats,
                                       const ParallelRuns& parallel = {});

/// One row per point: family list, label, settings, error, times, steps, front/default flags.
StudyTable convergence_table(const ConvergenceStudy& study);

/// Fixed-width table of the points, then the front and the default's place on it.
std::string convergence_report(const ConvergenceStudy& study);

/// The ladder over several scenes at once, the question a default answers:
/// which setting to use for all of them. A setting's worst |error| over the
/// scenes (none if it found no impact in one of them: never on the front)
/// against its summed median wall time. Settings are matched by label; only
/// those every scene ran count.
struct ConvergenceOverall {
  std::vector<std::string> labels;
  std::vector<double> worst_error;  ///< NaN where a scene had no measured error
  std::vector<double> total_cpu_s;  ///< summed median CPU time [s]
  std::vector<bool> is_default;     ///< the default of every scene
  std::vector<std::size_t> front;   ///< indices, by increasing total wall time
  std::optional<std::size_t> default_index;
  Domination default_domination;
};
ConvergenceOverall convergence_over_scenes(const std::vector<ConvergenceStudy>& studies);

std::string convergence_overall_report(const ConvergenceOverall& overall, std::size_t scene_count);

}  // namespace railjoint
