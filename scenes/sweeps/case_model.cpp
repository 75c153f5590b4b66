#include "scenes/sweeps/case_model.h"

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

}  // namespace railjoint
