#include "scenes/sweeps/case_models.h"

#include <limits>

#include "scenes/report/force_run_numbers.h"
#include "sim/simulate_crossing.h"
#include "sim/time_origin.h"
#include "support/input_error.h"

namespace railjoint {

namespace {

ModelOutcome run_forces(const CaseInput& input, CsvRow& row) {
  if (!(input.scene().sim.inertial() && input.scene().sim.inertial()->elastic())) {
    throw InputError(input.scene().file, "contact.law",
                     "the forces model needs a force run: sim.mode = \"inertial\" and contact.law = \"hertz\"");
  }
  // The case's crossing: the kinematic model's limits first, then the simulation's.
  const SimulationResult r = simulate_crossing(input.crossing());
  const ForceRunNumbers f = force_run_numbers(r);
  // Times on every output's one clock: 0 when the centre passes the
  // predicted impact (sim/time_origin.h), as simulate --json writes them.
  const double t0_s = simulation_time_origin_s(r);
  row.number(f.static_N);
  row.number(f.p1_N);
  row.number(f.p1_time_s - t0_s);
  row.number(f.p2_N);
  row.number(f.p2_time_s - t0_s);
  row.number(f.jenkins_p1_N);
  row.number(f.jenkins_p2_N);
  row.number(r.impact_found() ? r.impulse_Ns() : std::numeric_limits<double>::quiet_NaN());
  row.boolean(r.liftoff_time_s().has_value());
  row.integer(f.steps);
  row.boolean(f.p2_after_p1);
  row.boolean(f.p2_across_flight);
  row.integer(f.flights);
  row.number(f.flight_time_s);
  row.number(f.longest_flight_s);
  // The track's own forces (the lumped track's rail seat and ballast, as
  // simulate --json gives them); empty on tracks that do not record them.
  row.number(f.p2_rail_seat_N);
  row.number(f.rail_seat_peak_N);
  row.number(f.ballast_peak_N);
  if (!r.verdict.ok) return {CaseVerdict::suspect, "forces: " + r.verdict.reason};
  return {};
}

}  // namespace

CaseModel forces_case_model() {
  return {"forces",
          {"forces.static_N", "forces.p1_N", "forces.p1_time_s", "forces.p2_N", "forces.p2_time_s",
           "forces.jenkins_p1_N", "forces.jenkins_p2_N", "forces.pulse_impulse_Ns", "forces.liftoff", "forces.steps",
           "forces.p2_after_p1", "forces.p2_across_flight", "forces.flights", "forces.flight_time_s",
           "forces.longest_flight_s", "forces.p2_rail_seat_N", "forces.rail_seat_peak_N", "forces.ballast_peak_N"},
          run_forces};
}

}  // namespace railjoint
