#pragma once
// The analytic block of every JSON report (`railjoint analytic --json`, and
// `analytic` inside `simulate --json`). Every key with a unit ends in it
// (scenes/report/outputs.md); infinities become null.

#include <optional>

#include <nlohmann/json.hpp>

#include "models/impact_prediction.h"
#include "models/parameters.h"
#include "scenes/scene.h"

namespace railjoint {

nlohmann::json prediction_to_json(const ImpactPrediction& prediction);

/// The same crossing over a square joint (theta = 90 deg, every other key as
/// the scene's): the reference the thesis's design question reads an inclined
/// cut against (README, the design map).
struct SquareJointReference {
  double exact_Ns = 0.0;  ///< the square joint's exact jump [N s]
  double ratio = 0.0;     ///< this joint's exact jump over it
};
/// None for a step joint (no cut to turn), a square joint that has no
/// crossing (the wheel falls into its gap) and a level one (no jump).
std::optional<SquareJointReference> square_joint_reference(const JointParams& joint, const WheelParams& wheel,
                                                           const ImpactPrediction& prediction);

/// The analytic block of `analytic --json` and `simulate --json`: the
/// prediction for this joint and wheel with the square joint's jump beside it.
nlohmann::json analytic_block_to_json(const JointParams& joint, const WheelParams& wheel,
                                      const ImpactPrediction& prediction);

/// `analytic --json` (and Python's Prediction.as_dict()) but for the
/// profile_smoothing block: the analytic block and the scene it ran under.
nlohmann::json analytic_report_to_json(const Scene& scene, const ImpactPrediction& prediction);

/// The `profile_smoothing` block: each measured profile's file, tolerance
/// and residuals, the jump through the points and its relative change, and
/// `sensitive` (they differ by more than 1 %); null without a smoothed profile.
nlohmann::json profile_smoothing_json(const JointParams& joint, const WheelParams& wheel,
                                      const ImpactPrediction& prediction);

}  // namespace railjoint
