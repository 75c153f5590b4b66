#pragma once
// `railjoint simulate --json`: one JSON object, every key with a unit ending
// in it, times on the outputs' clock (t = 0 when the centre passes the
// predicted impact; scenes/report/outputs.md). `analytic` is
// exactly `railjoint analytic --json` of the scene, `analytic_as_simulated`
// the wheel Bullet holds (which `error` is against), `sim` the measurements
// (null where nothing was measured), `error` relative and signed. A new
// column of the simulate JSON goes here.

#include <nlohmann/json.hpp>

#include "sim/simulate_crossing.h"

namespace railjoint {

nlohmann::json simulation_json(const SimulationResult& result);

}  // namespace railjoint
