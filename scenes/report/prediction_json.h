#pragma once
// The analytic block of every JSON report (`railjoint analytic --json`, and
// `analytic` inside `simulate --json`). Every key with a unit ends in it
// (scenes/report/outputs.md); infinities become null.

#include <nlohmann/json.hpp>

#include "models/impact_prediction.h"

namespace railjoint {

nlohmann::json prediction_to_json(const ImpactPrediction& prediction);

}  // namespace railjoint
