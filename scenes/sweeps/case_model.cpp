#include "scenes/sweeps/case_model.h"

#include <iterator>

#include "scenes/scene_file.h"

namespace railjoint {

const char* to_string(CaseVerdict verdict) {
  constexpr const char* kNames[] = {"ok", "suspect", "no_impact", "failed", "rejected"};
  static_assert(std::size(kNames) == static_cast<std::size_t>(CaseVerdict::rejected) + 1, "a name per verdict");
  return kNames[static_cast<std::size_t>(verdict)];
}

const ImpactPrediction& CaseInput::prediction() const {
  if (scene_.prediction) return *scene_.prediction;
  if (!prediction_) prediction_ = predict_impact(scene_.joint, scene_.wheel);
  return *prediction_;
}

const std::shared_ptr<const CrossingModel>& CaseInput::crossing() const {
  if (!crossing_) {
    // The kinematic model's limits first, as `simulate`; a case's values are
    // the sweep file's, no --set, so no key is blamed as typed last.
    double rail_length_m = 0.0;
    crossing_ = scene_crossing(scene_, prediction(), no_key_given, rail_length_m);
  }
  return crossing_;
}

}  // namespace railjoint
