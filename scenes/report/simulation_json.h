#pragma once
// `railjoint simulate --json`: one JSON object, SI units. `analytic` is
// exactly `railjoint analytic --json` of the scene, `analytic_as_simulated`
// the wheel Bullet holds (which `error` is against), `sim` the measurements
// (null where nothing was measured), `error` relative and signed. A new
// column of the simulate JSON goes here.

#include <nlohmann/json.hpp>

#include "sim/simulate_crossing.h"

namespace railjoint {

nlohmann::json simulation_json(const SimulationResult& result);

}  // namespace railjoint
