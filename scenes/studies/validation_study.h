#pragma once
// The main job's measurement: one validation scene simulated (Bullet,
// kinematic mode) and its measured vertical momentum jump compared with the
// three analytic forms of the governing slice as simulated.

#include <vector>

#include "models/jump_error.h"
#include "scenes/scene.h"
#include "sim/simulate_crossing.h"
#include "support/case_pool.h"

namespace railjoint {

/// Every validation scene within 1e-4 of the exact form (issue 13), so the
/// simulation tells the three forms apart wherever they differ by more
/// than 3e-4; a run that cannot vouch for its number (sim.verdict) fails too.
inline constexpr double kValidationErrorBound = 1e-4;

struct ValidationRow {
  Scene scene;
  SimulationResult result;
  JumpErrors error;   ///< against each form of result.prediction()
  bool pass = false;  ///< an impact was found and |error.exact| <= kValidationErrorBound
};

ValidationRow validate_scene(const Scene& scene);

/// validate_scene of every scene, each on one of parallel.jobs threads; rows in the scenes' order.
std::vector<ValidationRow> validate_scenes(const std::vector<Scene>& scenes, const ParallelRuns& parallel = {});

struct ValidationSummary {
  int failures = 0;
  double worst_abs_error = 0.0;  ///< largest |error against the exact form|
  double wall_s = 0.0;           ///< simulation wall time of all rows
};

ValidationSummary summarize(const std::vector<ValidationRow>& rows);

}  // namespace railjoint
