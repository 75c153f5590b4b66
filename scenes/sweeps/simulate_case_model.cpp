#include "scenes/sweeps/case_models.h"

#include <limits>

#include "models/jump_error.h"
#include "sim/simulate_crossing.h"

namespace railjoint {

namespace {

ModelOutcome run_simulate(const CaseInput& input, CsvRow& row) {
  const Scene& scene = input.scene();
  const SimulationResult r = simulate_crossing(input.crossing());
  const ImpulseForms& f = r.prediction().impulse;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double jump = r.impact_found() ? r.impulse_Ns() : nan;
  // The errors as simulate --json's `error` (models/jump_error.h); NaN, an empty cell, without an impact.
  const JumpErrors error = jump_errors(jump, f);
  row.text(to_string(scene.sim.mode()));
  row.number(f.exact_Ns);
  row.number(jump);
  row.number(error.exact);
  row.number(error.thesis);
  row.number(error.small_angle);
  row.number(r.model->thin_disc_prediction ? relative_error(jump, r.model->thin_disc_prediction->impulse.exact_Ns)
                                           : nan);
  row.number(r.impact_found() ? r.impact->wheel_x_m() : nan);
  row.number(r.impact_found() ? r.impact->wheel_x_m() - r.prediction().impact_wheel_x_m : nan);
  row.boolean(r.liftoff_time_s().has_value());
  row.number(r.inertial() ? r.inertial()->total_impulse_Ns : nan);
  row.integer(r.steps);
  if (!r.impact_found()) return {CaseVerdict::no_impact, "simulate: no impact found at the joint"};
  // Inertial runs have no self-check (they are judged by their phases).
  if (!r.inertial() && !r.verdict.ok) return {CaseVerdict::suspect, "simulate: " + r.verdict.reason};
  return {};
}

}  // namespace

CaseModel simulate_case_model() {
  return {"simulate",
          {"simulate.mode", "simulate.exact_Ns", "simulate.jump_Ns", "simulate.error_exact", "simulate.error_thesis",
           "simulate.error_small_angle", "simulate.error_vs_thin_disc", "simulate.impact_x_m",
           "simulate.impact_x_error_m", "simulate.liftoff", "simulate.total_impulse_Ns", "simulate.steps"},
          run_simulate};
}

}  // namespace railjoint
