#include "models/finite_width_wheel.h"

#include <algorithm>
#include <cmath>

#include "models/inclined_joint.h"
#include "models/slice_profile.h"
#include "models/wheel_rail_envelope.h"

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

namespace {
// The governing slice meets the far rail while the wheel still rests on the
// near rail's top (on a step down: lands on the far rail's top). Touching
// both rail-end corners at once means it has dropped into the end-post gap
// first: an impact the thesis does not model, and one where the slice rule's
// derivation (the wheel on the incoming top) no longer holds.
bool drops_into_gap(const JointParams& joint, const WheelParams& wheel) {
  const TwoPointContact contact =
      solve_two_point_contact(slice_profile(joint, governing_slice_y_m(joint, wheel)), wheel.radius_m);
  return contact.incoming.at_corner && contact.outgoing.at_corner;
}
}  // namespace

bool governing_slice_rule_holds(const JointParams& joint, const WheelParams& wheel) {
  if (!has_thesis_geometry(joint, wheel)) return false;
  if (joint.gap_m == 0.0) return true;
  if (drops_into_gap(joint, wheel)) return false;
  if (wheel.width_m == 0.0 || joint.kind == JointKind::step) return true;
  return is_square_joint(joint.theta_rad) || select_governing_slice(joint, wheel).configuration == 5;
}

double governing_slice_y_m(const JointParams& joint, const WheelParams& wheel) {
  return joint.kind == JointKind::step ? wheel.lateral_m : select_governing_slice(joint, wheel).governing_y_m;
}

}  // namespace railjoint
