#pragma once
// `railjoint simulate --csv`: the recorded time series, one row per sample:
// t, x, z, zdot, contact count, summed vertical contact impulse, xdot,
// vertical contact force (impulse / step), the kinematic centre height at x
// (inertial: with the flat approach), spin rate. SI units.

#include <ostream>

#include "sim/simulate_crossing.h"

namespace railjoint {

void write_simulation_csv(const SimulationResult& result, std::ostream& out);

}  // namespace railjoint
