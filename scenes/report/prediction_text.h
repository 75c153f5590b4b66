#pragma once
// The text summary of `railjoint analytic`: the joint and wheel, the contact
// scenario and configuration, x_A by both routes, the contact points, and the
// jump in its three forms with their differences from the exact one.

#include "models/impact_prediction.h"
#include "scenes/scene.h"

namespace railjoint {

void print_prediction_summary(const Scene& scene, const ImpactPrediction& prediction);

}  // namespace railjoint
