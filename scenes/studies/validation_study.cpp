#include "scenes/studies/validation_study.h"

#include <algorithm>
#include <cmath>

namespace railjoint {

ValidationRow validate_scene(const Scene& scene) {
  ValidationRow row;
  row.scene = scene;
  row.result = simulate_crossing(scene.joint, scene.wheel, scene.sim);
  row.error = jump_errors(row.result.impulse_Ns(), row.result.prediction().impulse);
  row.pass = row.result.impact_found() && row.result.verdict.ok && std::abs(row.error.exact) <= kValidationErrorBound;
  return row;
}

std::vector<ValidationRow> validate_scenes(const std::vector<Scene>& scenes, const ParallelRuns& parallel) {
  return parallel_map<ValidationRow>(scenes.size(), parallel, [&](std::size_t i) { return validate_scene(scenes[i]); });
}

ValidationSummary summarize(const std::vector<ValidationRow>& rows) {
  ValidationSummary summary;
  summary.failures = static_cast<int>(std::count_if(rows.begin(), rows.end(), [](const auto& r) { return !r.pass; }));
  for (const ValidationRow& r : rows) {
    summary.worst_abs_error = std::max(summary.worst_abs_error, std::abs(r.error.exact));
    summary.wall_s += r.result.wall_seconds;
  }
  return summary;
}

}  // namespace railjoint
