#pragma once
// The single entry point of the simulation: build the model of one wheel
// crossing one joint (crossing_model.h), run the one stepping loop
// (crossing_run.h) and measure the vertical momentum jump against the
// analytic prediction (crossing_analysis.h). Used by `railjoint simulate`,
// `validate`, `render`, the studies, the tests and the benchmarks. No Bullet
// in this header; what a run gives is simulation_result.h.

#include <memory>

#include "models/parameters.h"
#include "sim/crossing_model.h"
#include "sim/sim_settings.h"
#include "sim/simulation_result.h"

namespace railjoint {

/// Runs a checked crossing (build_crossing_model, crossing_model.h): what a
/// scene read for a simulation holds (Scene::crossing).
SimulationResult simulate_crossing(std::shared_ptr<const CrossingModel> model);

/// Checks and builds the crossing, then runs it. Throws InputError for
/// parameters outside the model (key "joint.*", "wheel.*") or settings that
/// cannot work together (key "sim.*").
SimulationResult simulate_crossing(const JointParams& joint, const WheelParams& wheel, const SimSettings& settings);

}  // namespace railjoint
