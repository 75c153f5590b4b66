#pragma once
// The kinematic model's answer as Python sees it (railjoint.Prediction):
// the prediction and, for railjoint.analytic(), the scene it was made for,
// whose keys its as_dict() reports as `analytic --json` does. The
// predictions inside a simulation carry no scene, as in `simulate --json`.

#include <memory>
#include <optional>

#include <nlohmann/json.hpp>
#include <pybind11/pybind11.h>

#include "models/impact_prediction.h"
#include "scenes/scene.h"

namespace railjoint::python {

struct PredictionResult {
  ImpactPrediction prediction;
  std::shared_ptr<const Scene> scene;  ///< null inside a simulation's report
  /// The `profile_smoothing` block where the JSON it mirrors has one (scenes/report/prediction_json.h).
  std::optional<nlohmann::json> profile_smoothing = std::nullopt;
  /// A simulation's `analytic` block whole, as simulate --json writes it (with the square joint's jump).
  std::optional<nlohmann::json> json_block = std::nullopt;
  pybind11::object frozen = pybind11::object();  ///< an unpickled one's state (frozen_result.h); null otherwise
};

/// Adds the class railjoint.Prediction.
void bind_prediction_class(pybind11::module_& m);

}  // namespace railjoint::python
