#pragma once
// What a run of the stepping loop means: passes over the recorded
// trajectory that find the impacts, measure the jump at the joint and fill
// in the SimulationResult. The kinematic pass picks the jump nearest the
// predicted impact and checks the run against the prediction (self_check.h);
// the inertial pass adds every contact phase, flight and landing, and the
// comparisons with the lift-off model and, for a compliant contact, with P1.

#include <memory>

#include "sim/crossing_model.h"
#include "sim/crossing_run.h"
#include "sim/simulation_result.h"

namespace railjoint {

SimulationResult analyse_kinematic_crossing(std::shared_ptr<const CrossingModel> model, CrossingRun run);

SimulationResult analyse_inertial_crossing(std::shared_ptr<const CrossingModel> model, CrossingRun run);

}  // namespace railjoint
