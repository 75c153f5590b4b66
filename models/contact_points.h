#pragma once
// Top view of the two-point contact across the rail head (thesis figure 4.8):
// for a thin disc at each lateral position, where the cut is, where the wheel
// centre line is and where contact points A and B lie.

#include <vector>

#include "models/impact_prediction.h"
#include "models/parameters.h"

namespace railjoint {

struct TopViewContact {
  double y_m = 0.0;
  double cut_x_m = 0.0;      ///< the cut at this y [m]
  double wheel_x_m = 0.0;    ///< wheel centre line at the two-point contact [m]
  double A_x_m = 0.0;        ///< contact point A [m]
  double B_x_m = 0.0;        ///< contact point B [m]
  ImpactScenario scenario = ImpactScenario::one;
  bool on_landing = false;
};

/// `samples` (>= 2) lateral positions evenly spaced over [-b_t, b_t].
std::vector<TopViewContact> top_view_contacts(const JointParams& joint, const WheelParams& wheel, int samples);

}  // namespace railjoint
