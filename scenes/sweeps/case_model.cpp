#include "scenes/sweeps/case_model.h"

#include "scenes/scene_file.h"
#include "sim/crossing_model.h"
#include "support/input_error.h"

namespace railjoint {

const char* to_string(CaseVerdict verdict) {
  switch (verdict) {
    case CaseVerdict::ok:
      return "ok";
    case CaseVerdict::suspect:
      return "suspect";
    case CaseVerdict::no_impact:
      return "no_impact";
    case CaseVerdict::failed:
      return "failed";
    case CaseVerdict::rejected:
      return "rejected";
  }
  return "unknown";
}

const ImpactPrediction& CaseInput::prediction() const {
  if (scene_.prediction) return *scene_.prediction;
  if (!prediction_) prediction_ = predict_impact(scene_.joint, scene_.wheel);
  return *prediction_;
}

const std::shared_ptr<const CrossingModel>& CaseInput::crossing() const {
  if (!crossing_) {
    const Scene& s = scene_;
    const ImpactPrediction& scene_wheel = prediction();  // the kinematic model's limits first, as `simulate`
    // A prediction the simulated wheel cannot have is left to the build, which
    // checks the inputs first and so blames the right key (as load_scene).
    std::optional<CrossingPredictions> predictions;
    try {
      predictions = predict_crossing(s.joint, s.wheel, s.sim, &scene_wheel);
    } catch (const InputError&) {
    }
    // The rails for the run, derived from those predictions as `simulate` does.
    JointParams joint = s.joint;
    joint.length_m = simulated_rail_length_m(s, predictions ? &*predictions : nullptr);
    crossing_ = std::make_shared<const CrossingModel>(
        build_crossing_model(joint, s.wheel, s.sim, predictions ? &*predictions : nullptr));
  }
  return crossing_;
}

}  // namespace railjoint
