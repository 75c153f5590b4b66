#pragma once
// The main job's measurement: one validation scene simulated (Bullet,
// kinematic mode) and its measured vertical momentum jump compared with the
// three analytic forms of the governing slice as simulated.

#include <vector>

#include "models/jump_error.h"
#include "scenes/scene.h"
#include "sim/simulate_crossing.h"

namespace railjoint {

/// DESIGN.md / issue 4: every validation scene within 0.5 % of the exact form.
inline constexpr double kValidationErrorBound = 5e-3;

struct ValidationRow {
  Scene scene;
  SimulationResult result;
  JumpErrors error;   ///< against each form of result.prediction
  bool pass = false;  ///< an impact was found and |error.exact| <= kValidationErrorBound
};

ValidationRow validate_scene(const Scene& scene);

struct ValidationSummary {
  int failures = 0;
  double worst_abs_error = 0.0;  ///< largest |error against the exact form|
  double wall_s = 0.0;           ///< simulation wall time of all rows
};

ValidationSummary summarize(const std::vector<ValidationRow>& rows);

}  // namespace railjoint
