#include "models/contact_points.h"

#include <cassert>

#include "models/inclined_joint.h"

namespace railjoint {

std::vector<TopViewContact> top_view_contacts(const JointParams& joint, const WheelParams& wheel, int samples) {
  assert(samples >= 2);
  std::vector<TopViewContact> rows;
  WheelParams disc = wheel;
  disc.width_m = 0.0;
  for (int i = 0; i < samples; ++i) {
    disc.lateral_m = -joint.half_width_m + 2.0 * joint.half_width_m * i / (samples - 1);
    const ImpactPrediction p = predict_impact(joint, disc);
    rows.push_back({disc.lateral_m, cut_x_m(joint.theta_rad, disc.lateral_m), p.impact_wheel_x_m, p.contact_A_m.x(),
                    p.contact_B_m.x(), p.scenario, p.on_landing});
  }
  return rows;
}

}  // namespace railjoint
