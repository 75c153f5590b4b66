#pragma once
// The analytic block of every JSON report (`railjoint analytic --json`, and
// `analytic` inside `simulate --json`). Every key with a unit ends in it
// (scenes/report/outputs.md); infinities become null.

#include <nlohmann/json.hpp>

#include "models/impact_prediction.h"
#include "models/parameters.h"

namespace railjoint {

nlohmann::json prediction_to_json(const ImpactPrediction& prediction);

/// The `profile_smoothing` block: each measured profile's file, tolerance
/// and residuals, the jump through the points and its relative change, and
/// `sensitive` (they differ by more than 1 %); null without a smoothed profile.
nlohmann::json profile_smoothing_json(const JointParams& joint, const WheelParams& wheel,
                                      const ImpactPrediction& prediction);

}  // namespace railjoint
