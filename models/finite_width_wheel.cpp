#include "models/finite_width_wheel.h"

#include <algorithm>
#include <cmath>

#include "models/inclined_joint.h"

namespace railjoint {

SliceSelection select_governing_slice(const JointParams& joint, const WheelParams& wheel) {
  const double y_t = transition_y_m(joint, wheel.radius_m);
  const double y_w = wheel.lateral_m;
  SliceSelection selection;
  if (wheel.width_m == 0.0) {
    selection.governing_y_m = y_w;
    selection.scenario_one = std::abs(y_w) <= y_t;
    return selection;
  }
  // Part of the wheel that stands on the rail head.
  const double lo = std::max(y_w - wheel.width_m / 2.0, -joint.half_width_m);
  const double hi = std::min(y_w + wheel.width_m / 2.0, joint.half_width_m);
  const double band_lo = std::max(lo, -y_t);
  const double band_hi = std::min(hi, y_t);
  // Edge-on contact with the band (a single disc) counts as inside it; allow
  // round-off of the caller's arithmetic (e.g. y_w = y_t + b_w / 2).
  const double touch_tolerance_m = 1e-12;
  selection.scenario_one = band_hi >= band_lo - touch_tolerance_m;
  if (selection.scenario_one) {
    selection.governing_y_m = std::clamp(y_w, -y_t, y_t);
    selection.line_contact_length_m = std::max(0.0, band_hi - band_lo);
    const double on_head = hi - lo;
    if (selection.line_contact_length_m <= touch_tolerance_m) {
      selection.configuration = 4;
    } else if (selection.line_contact_length_m >= on_head - touch_tolerance_m) {
      selection.configuration = (lo <= 0.0 && hi >= 0.0) ? 1 : 2;
    } else {
      selection.configuration = 3;
    }
  } else {
    selection.governing_y_m = y_w > 0.0 ? lo : hi;
    selection.configuration = 5;
  }
  return selection;
}

}  // namespace railjoint
