#pragma once
// The general kinematic model: any wheel that is a surface of revolution
// about its axle, on any rail top that is a lateral head profile plus a dip
// along x, over an end-post gap or not (the thesis's recommendation 7.2.1).
//
// A rail point at lateral y lies inside the wheel exactly when it lies inside
// the circle of radius r(y) (wheel_tread.h) in the wheel's slice through y.
// So the lowest centre height at which the wheel touches but does not cut a
// rail is, for the centre at x, the highest over the wheel's lateral span on
// the head of each slice's support:
//   S(y, x) = c(y) + max over the rail's x' in slice y of [ d(x') + sqrt(r(y)^2 - (x - x')^2) ],
// c the head's crown (rail_head.h), d the dip (dip_profile.h), x' up to the
// rail end's cut at y (rail_top.h). The centre path is the higher of the two
// rails' envelopes, and the jump is the change of its slope where the
// outgoing rail's envelope overtakes the incoming one's (envelope theorem:
// the slope is dS/dx at the maximising slice and rail point).
//
// Why the maximum over y is unique and found to round-off: the bracket is
// jointly concave in (y, x') (a concave crown and dip, r linear in y, and
// sqrt(r^2 - u^2) concave on r >= |u| with (r, u) linear in (y, x')), and
// the set {x' <= cut(y)} is convex, so S is concave in y. dS/dy (in closed
// form, with the cut edge's own term when the contact sits on it) therefore
// falls through zero once, and a bracketing root search (TOMS 748) finds
// that zero to the last bits. tests/models/wheel_rail_envelope_test.cpp
// checks the model against an independent reference and the thesis's
// closed forms.

#include <limits>

#include <Eigen/Core>

#include "models/parameters.h"

namespace railjoint {

/// The part of the wheel that stands on the rail head [m] (lo = hi for a thin disc).
struct LateralSpan {
  double lo_m = 0.0;
  double hi_m = 0.0;
};
LateralSpan wheel_span_on_head(const JointParams& joint, const WheelParams& wheel);

/// Where one rail holds the wheel up when its centre is at x.
struct RailSupport {
  double centre_z_m = -std::numeric_limits<double>::infinity();  ///< lowest centre height not cutting the rail [m]; -inf: out of reach
  double slope = 0.0;                                             ///< d(centre_z)/dx [-]
  Eigen::Vector3d contact_m = Eigen::Vector3d::Zero();            ///< touching point on the rail top [m]
  bool at_cut_edge = false;  ///< the contact is on the rail end's edge at the cut (the wheel pivots about it)
};

/// Support of the whole wheel by rail 0 (incoming) or 1 (outgoing).
RailSupport rail_support(const JointParams& joint, const WheelParams& wheel, int rail, double centre_x_m);

/// Support of the wheel's one slice at lateral y by a rail.
RailSupport slice_rail_support(const JointParams& joint, const WheelParams& wheel, int rail, double y_m,
                               double centre_x_m);

/// The instant the outgoing rail takes over: the two rails hold the centre
/// equally high (to round-off), with each rail's support there. A support
/// is -inf where no x lets both rails reach the wheel (a gap longer along
/// the track than the wheel can bridge).
struct EnvelopeContact {
  double centre_x_m = 0.0;
  double centre_z_m = 0.0;
  RailSupport incoming;
  RailSupport outgoing;
};
EnvelopeContact solve_envelope_contact(const JointParams& joint, const WheelParams& wheel);

/// The thesis's geometry: flat head, cylindrical tread, linear dip. Its
/// closed forms and the governing-slice rule of section 3.3.5 hold there.
bool has_thesis_geometry(const JointParams& joint, const WheelParams& wheel);

}  // namespace railjoint
