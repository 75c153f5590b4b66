#pragma once
// The text report of `railjoint simulate` on stdout: settings, the impact
// against the prediction (time, position, contact points struck and left),
// the measured jump and its error against each analytic form; in inertial
// mode every contact phase, flight and impact, the lift-off model and the
// compliant contact's peak force against P1.

#include "scenes/scene.h"
#include "sim/simulate_crossing.h"

namespace railjoint {

void print_simulation_summary(const Scene& scene, const SimulationResult& result);

/// Three lines for `railjoint render`: the scene, the impact, the jump against the exact form.
void print_simulation_brief(const Scene& scene, const SimulationResult& result);

/// Only for a run in inertial mode (result.inertial set).
void print_inertial_summary(const SimulationResult& result);

}  // namespace railjoint
