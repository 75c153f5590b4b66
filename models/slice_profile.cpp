#include "models/slice_profile.h"

#include <cassert>
#include <cmath>
#include <limits>

#include "models/inclined_joint.h"

namespace railjoint {

SliceProfile slice_profile(const JointParams& joint, double y_m) {
  const double half_length = joint.length_m / 2.0;
  if (joint.kind == JointKind::step) {
    const double half_gap = gap_half_shift_m(joint);
    const double u0 = joint.step_height_m;
    return {ProfileSegment{{-half_length, 0.0}, {-half_gap, 0.0}},
            ProfileSegment{{half_gap, u0}, {half_length, u0}}};
  }
  const double t = std::tan(joint.beta_rad / 2.0);
  const double half_gap_x = gap_half_shift_m(joint);
  const double x_in_end = cut_x_m(joint.theta_rad, y_m) - half_gap_x;
  const double x_out_start = cut_x_m(joint.theta_rad, y_m) + half_gap_x;
  return {ProfileSegment{{-half_length, t * half_length}, {x_in_end, -t * x_in_end}},
          ProfileSegment{{x_out_start, t * x_out_start}, {half_length, t * half_length}}};
}

namespace {
SegmentSupport corner_support(const Eigen::Vector2d& corner, double radius_m, double centre_x_m) {
  SegmentSupport support;
  support.contact_m = corner;
  support.at_corner = true;
  const double dx = centre_x_m - corner.x();
  if (std::abs(dx) > radius_m) {
    support.centre_z_m = -std::numeric_limits<double>::infinity();
    return support;
  }
  const double h = std::sqrt(radius_m * radius_m - dx * dx);
  support.centre_z_m = corner.y() + h;
  support.slope = -dx / h;
  return support;
}
}  // namespace

SegmentSupport segment_support(const ProfileSegment& segment, double radius_m, double centre_x_m) {
  const Eigen::Vector2d direction = segment.end_m - segment.start_m;
  assert(direction.x() > 0.0);
  const double m = direction.y() / direction.x();
  const double root = std::sqrt(1.0 + m * m);
  // Centre = contact + R n with the upward normal n = (-m, 1) / sqrt(1 + m^2):
  // the tangent point lies R m / sqrt(1 + m^2) ahead of the centre.
  const double contact_x = centre_x_m + radius_m * m / root;
  if (contact_x < segment.start_m.x()) return corner_support(segment.start_m, radius_m, centre_x_m);
  if (contact_x > segment.end_m.x()) return corner_support(segment.end_m, radius_m, centre_x_m);
  SegmentSupport support;
  support.contact_m = {contact_x, segment.start_m.y() + m * (contact_x - segment.start_m.x())};
  support.centre_z_m = support.contact_m.y() + radius_m / root;
  support.slope = m;
  return support;
}

SegmentSupport profile_support(const SliceProfile& profile, double radius_m, double centre_x_m) {
  const SegmentSupport in = segment_support(profile[0], radius_m, centre_x_m);
  const SegmentSupport out = segment_support(profile[1], radius_m, centre_x_m);
  return out.centre_z_m > in.centre_z_m ? out : in;
}

TwoPointContact solve_two_point_contact(const SliceProfile& profile, double radius_m) {
  // g(x) = f_out(x) - f_in(x) is < 0 while the incoming rail carries the wheel
  // and > 0 once the outgoing one does; one circle radius either side of the
  // joint brackets the change.
  double lo = profile[0].end_m.x() - radius_m;
  double hi = profile[1].start_m.x() + radius_m;
  const auto g = [&](double x) {
    return segment_support(profile[1], radius_m, x).centre_z_m - segment_support(profile[0], radius_m, x).centre_z_m;
  };
  assert(g(lo) < 0.0 && g(hi) > 0.0);
  for (int i = 0; i < 200 && hi - lo > 0.0; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;  // round-off reached
    (g(mid) < 0.0 ? lo : hi) = mid;
  }
  TwoPointContact contact;
  contact.centre_x_m = 0.5 * (lo + hi);
  contact.incoming = segment_support(profile[0], radius_m, contact.centre_x_m);
  contact.outgoing = segment_support(profile[1], radius_m, contact.centre_x_m);
  contact.centre_z_m = std::max(contact.incoming.centre_z_m, contact.outgoing.centre_z_m);
  return contact;
}

}  // namespace railjoint
