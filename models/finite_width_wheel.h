#pragma once
// A wheel of finite width b_w as rigidly joined thin discs (thesis section
// 3.3.5): which slice governs the impact, the thesis's configuration 1-5, and
// the length of the line contact.
//
// Derivation (tests/models/finite_width_wheel_test.cpp checks it): every slice
// runs on the same incoming top z = -tan(beta/2) x and meets the same outgoing
// top z = +tan(beta/2) x; only where each rail ends differs. A slice with
// |y| <= y_t meets the outgoing top at its tangent point (the plain V), any
// other slice at a corner on that line, which the V-tangent circle never cuts.
// So a cylinder overlapping the band |y| <= y_t has the scenario-1 impulse,
// with line contact over the overlap. Otherwise, for y_w > 0, the corner
// height t*x_c + sqrt(R^2 - (x_w - x_c)^2) falls with x_c while
// tan(alpha) > tan(beta/2), so the slice nearest the centre line strikes
// first and keeps the pivot; for y_w < 0 (step down) the same slice is the
// last to let go and lands first. Either way the inner edge governs.

#include <optional>

#include "models/parameters.h"

namespace railjoint {

struct SliceSelection {
  double governing_y_m = 0.0;           ///< lateral position of the slice that governs [m]
  bool scenario_one = true;             ///< the cylinder overlaps the band |y| <= y_t
  double line_contact_length_m = 0.0;   ///< overlap of the wheel with that band on the rail head [m]
  /// Figure 3.21 configuration (empty for a thin disc). Our reading of the figure:
  /// 1 whole width in the band and over the track centre line, 2 whole width in the
  /// band off the centre line, 3 partly in the band (line contact shortened),
  /// 4 only the inner edge at y_t (point contact, scenario 1), 5 outside the band
  /// (point contact at the inner edge, scenario 2).
  std::optional<int> configuration;
};

/// For an inclined joint; a thin disc (width 0) returns its own plane.
SliceSelection select_governing_slice(const JointParams& joint, const WheelParams& wheel);

/// Whether one slice carries the wheel along its whole path, so that the
/// thesis's model (that slice's profile, slice_profile.h) is exact: the
/// thesis's geometry (flat head, cylinder, linear dip; wheel_rail_envelope.h)
/// and no end-post gap under a wheel of finite width, except on a square cut
/// (all slices alike) and in configuration 5 (every slice strikes the cut
/// edge), and no gap the governing slice drops into (it would pivot over the
/// near rail's corner and strike the far one's). Elsewhere other slices carry
/// the wheel, and the general model (the envelope over all slices) holds.
bool governing_slice_rule_holds(const JointParams& joint, const WheelParams& wheel);

/// The slice the thesis's model solves [m]: the wheel's own plane on a step
/// joint, select_governing_slice's on an inclined one.
double governing_slice_y_m(const JointParams& joint, const WheelParams& wheel);

}  // namespace railjoint
