#pragma once
// `railjoint simulate --csv` and Simulation.trajectory: the recorded time
// series, one row per sample: t (0 when the centre passes the predicted
// impact position), x, z (joint frame), zdot, contact count, summed vertical
// contact impulse, xdot, vertical contact force (impulse / time it bore the load), the
// kinematic centre height at x (inertial: with the flat approach), spin
// rate; a force run adds the track under the wheel and where the contact
// bears, the lumped track its support forces, a bogie each wheel's force.
// Columns and origins: scenes/report/outputs.md.

#include <ostream>

#include "scenes/report/column_table.h"
#include "sim/simulate_crossing.h"

namespace railjoint {

ColumnTable simulation_table(const SimulationResult& result);

/// simulation_table as CSV (write_csv).
void write_simulation_csv(const SimulationResult& result, std::ostream& out);

}  // namespace railjoint
