#include "scenes/sweeps/case_models.h"

namespace railjoint {

namespace {

ModelOutcome run_analytic(const CaseInput& input, CsvRow& row) {
  const ImpactPrediction& p = input.prediction();
  row.text(p.scenario == ImpactScenario::step ? "step" : p.scenario == ImpactScenario::one ? "1" : "2");
  row.boolean(p.on_landing);
  row.number(p.transition_y_m);
  row.number(p.governing_y_m);
  if (p.configuration) {
    row.integer(*p.configuration);
  } else {
    row.empty();
  }
  row.number(p.x_A_m);
  row.number(p.alpha_rad);
  row.number(p.impulse.exact_Ns);
  row.number(p.impulse.thesis_Ns);
  row.number(p.impulse.small_angle_Ns);
  return {};
}

}  // namespace

CaseModel analytic_case_model() {
  return {"analytic",
          {"analytic.scenario", "analytic.on_landing", "analytic.y_t_m", "analytic.governing_y_m",
           "analytic.configuration", "analytic.x_A_m", "analytic.alpha_rad", "analytic.exact_Ns", "analytic.thesis_Ns",
           "analytic.small_angle_Ns"},
          run_analytic};
}

}  // namespace railjoint
