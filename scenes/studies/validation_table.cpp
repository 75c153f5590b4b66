// The validation table (validation_table.h).

#include "scenes/studies/validation_table.h"


namespace railjoint {

namespace {

std::string scenario_label(const ImpactPrediction& p, bool thin_disc_scene) {
  std::string label = p.scenario == ImpactScenario::step ? "step" : std::string("s") + to_string(p.scenario);
  // A thin disc is simulated as a narrow cylinder; its configuration is not the scene's.
  if (p.configuration && !thin_disc_scene) label += " c" + std::to_string(*p.configuration);
  if (p.on_landing) label += " landing";
  return label;
}

}  // namespace

const char* const kValidationHeader =
    // validation_table's printed columns, abbreviated; the errors are relative, (sim - form) / form.
    "scene                   scenario        exact Ns   thesis Ns    small Ns      sim Ns   err exact  err thesis   err small  wall ms";

StudyTable validation_table(const std::vector<ValidationRow>& rows) {
  StudyTable table({{"scene", "scene", "%-22s"}, {"scenario", "scenario", "%-12s"}, {"governing_y_m"},
                    {"analytic_exact_Ns", "exact [N s]", "%10.3f"}, {"analytic_thesis_Ns", "thesis [N s]", "%10.3f"},
                    {"analytic_small_angle_Ns", "small angle [N s]", "%10.3f"}, {"sim_Ns", "simulated [N s]", "%10.3f"},
                    {"sim_from_contacts_Ns"}, {"error_exact", "error vs exact", "%+10.1e"},
                    {"error_thesis", "vs thesis", "%+10.1e"}, {"error_small_angle", "vs small angle", "%+10.1e"},
                    {"impact_x_predicted_m"}, {"impact_x_sim_m"}, {"max_penetration_m"}, {"liftoff"},
                    {"wall_ms", "wall [ms]", "%7.1f"}, {"steps"}, {"pass", "within 1e-4", "%-s"}});
  for (const ValidationRow& r : rows) {
    const ImpactPrediction& p = r.result.prediction();
    const auto& impact = r.result.impact;
    table.add({r.scene.name, scenario_label(p, r.scene.wheel.width_m == 0.0), p.governing_y_m, p.impulse.exact_Ns,
               p.impulse.thesis_Ns, p.impulse.small_angle_Ns, r.result.impulse_Ns(),
               impact ? impact->impulse_from_contacts_Ns() : kNaN, r.error.exact, r.error.thesis, r.error.small_angle,
               p.impact_wheel_x_m, impact ? impact->wheel_x_m() : kNaN, r.result.max_penetration_m,
               r.result.liftoff_time_s().has_value(), r.result.wall_seconds * 1e3, r.result.steps,
               {r.pass, r.pass ? "ok" : r.result.verdict.ok ? "FAIL" : "FAIL (suspect)"}});
  }
  return table;
}

}  // namespace railjoint
