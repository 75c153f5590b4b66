#pragma once
// `railjoint simulate --csv`: the recorded time series, one row per sample:
// t (0 when the centre passes the predicted impact position), x, z (joint
// frame), zdot, contact count, summed vertical contact impulse, xdot,
// vertical contact force (impulse / step), the kinematic centre height at x
// (inertial: with the flat approach), spin rate. Columns and origins:
// scenes/report/outputs.md.

#include <ostream>

#include "sim/simulate_crossing.h"

namespace railjoint {

void write_simulation_csv(const SimulationResult& result, std::ostream& out);

}  // namespace railjoint
