#pragma once
// The rail tops seen by one thin slice of the wheel (the vertical plane at
// lateral y), as straight segments in the x-z plane, and the exact solve of
// where a circle of radius R resting on them has its centre. This is the
// "exact geometric solve" that generalises: a gap between the rail ends, a
// step up or down, any polyline dip.

#include <array>

#include <Eigen/Core>

#include "models/parameters.h"

namespace railjoint {

/// A straight piece of rail top in the x-z plane, start.x() < end.x().
struct ProfileSegment {
  Eigen::Vector2d start_m;
  Eigen::Vector2d end_m;
};

/// Incoming rail top (index 0) and outgoing rail top (index 1) at lateral y.
using SliceProfile = std::array<ProfileSegment, 2>;

/// The profile of a joint at lateral y (inclined: linear dip cut at
/// y cot(theta), each rail end shortened by half the gap normal to the cut;
/// step: flat rails, the outgoing one at u0).
SliceProfile slice_profile(const JointParams& joint, double y_m);

/// Where a circle of radius R with centre at x is held up by one segment.
struct SegmentSupport {
  double centre_z_m = 0.0;     ///< lowest centre height that does not cut the segment [m] (-inf: out of reach)
  double slope = 0.0;          ///< d(centre_z)/dx [-]
  Eigen::Vector2d contact_m;   ///< touching point on the segment [m]
  bool at_corner = false;      ///< the contact is an end point of the segment (pivot about an edge)
};

SegmentSupport segment_support(const ProfileSegment& segment, double radius_m, double centre_x_m);

/// The two-point contact: where the support passes from the incoming to the
/// outgoing rail, with the one-sided slopes of the centre path there.
struct TwoPointContact {
  double centre_x_m = 0.0;
  double centre_z_m = 0.0;
  SegmentSupport incoming;  ///< support by the incoming rail at that instant (B, or the corner on a step down)
  SegmentSupport outgoing;  ///< support by the outgoing rail (A)
};

/// Solves f_out(x) = f_in(x) by bisection to round-off. Requires the profile
/// to be crossed by a circle of radius R (the rails long enough).
TwoPointContact solve_two_point_contact(const SliceProfile& profile, double radius_m);

}  // namespace railjoint
