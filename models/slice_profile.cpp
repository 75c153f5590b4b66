#include "models/slice_profile.h"

#include <cassert>
#include <cmath>
#include <limits>

#include "models/dip_profile.h"
#include "models/rail_top.h"

namespace railjoint {

SliceProfile slice_profile(const JointParams& joint, double y_m) {
  // The rail surface of rail_top.h, cut where each rail ends at y. Each rail
  // top is one straight piece along x (a dip of several pieces would need a
  // polyline here).
  assert(joint.kind == JointKind::step || dip_pieces_along_x(joint) == 1);
  const double half_length = joint.length_m / 2.0;
  const double x_in_end = cut_x_m(joint, y_m, 0);
  const double x_out_start = cut_x_m(joint, y_m, 1);
  return {ProfileSegment{{-half_length, rail_surface_height_m(joint, 0, -half_length)},
                         {x_in_end, rail_surface_height_m(joint, 0, x_in_end)}},
          ProfileSegment{{x_out_start, rail_surface_height_m(joint, 1, x_out_start)},
                         {half_length, rail_surface_height_m(joint, 1, half_length)}}};
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
