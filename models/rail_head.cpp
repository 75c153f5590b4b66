#include "models/rail_head.h"

#include "models/profile_curve.h"

#include <array>
#include <algorithm>
#include <cmath>
#include <limits>

namespace railjoint {

namespace {

struct Arc {
  double radius_m;
  double centre_y_m;  // for y >= 0
  double centre_z_m;
  double to_y_m;      // the arc serves up to this |y|
};

// 60E1's three tangent arcs for y >= 0 (rail_head.h): each centre lies on
// the previous arc's radius through the point where it ends, its own radius
// from that point.
std::array<Arc, 3> arcs_60e1() {
  constexpr double kR1 = 0.300, kR2 = 0.080, kR3 = 0.013;
  constexpr double kY1 = 0.020456 / 2.0, kY2 = 0.052053 / 2.0;
  const Arc first{kR1, 0.0, -kR1, kY1};
  const auto next = [](const Arc& a, double radius_m, double to_y_m) {
    const double y = a.to_y_m;
    const double z = a.centre_z_m + std::sqrt(a.radius_m * a.radius_m - (y - a.centre_y_m) * (y - a.centre_y_m));
    const double k = radius_m / a.radius_m;
    return Arc{radius_m, y + k * (a.centre_y_m - y), z + k * (a.centre_z_m - z), to_y_m};
  };
  const Arc second = next(first, kR2, kY2);
  Arc third = next(second, kR3, 0.0);
  // Down to where the side leans 1:20 from the vertical: dz/dy = -20.
  third.to_y_m = third.centre_y_m + 20.0 * kR3 / std::sqrt(401.0);
  return {first, second, third};
}

const std::array<Arc, 3>& profile_60e1() {
  static const std::array<Arc, 3> arcs = arcs_60e1();
  return arcs;
}

// The arc that serves |y| (the last one beyond its end: callers keep |y|
// within the head's half-width).
const Arc& arc_at(double abs_y_m) {
  const std::array<Arc, 3>& arcs = profile_60e1();
  for (const Arc& a : arcs) {
    if (abs_y_m <= a.to_y_m) return a;
  }
  return arcs.back();
}

}  // namespace

bool has_flat_head(const JointParams& joint) {
  return joint.rail_profile == RailProfile::arc && joint.crown_radius_m == 0.0;
}

double head_top_height_m(const JointParams& joint, double y_m) {
  if (joint.rail_profile == RailProfile::measured) return joint.measured_head->value_m(y_m) - joint.measured_head->max_value_m();
  if (joint.rail_profile == RailProfile::en_60e1) {
    const Arc& a = arc_at(std::abs(y_m));
    const double u = std::abs(y_m) - a.centre_y_m;
    return a.centre_z_m + std::sqrt((a.radius_m - u) * (a.radius_m + u));
  }
  if (has_flat_head(joint)) return 0.0;
  const double rho = joint.crown_radius_m;
  // -y^2 / (rho + sqrt(rho^2 - y^2)): the same value without the cancellation
  // of sqrt(rho^2 - y^2) - rho near the crest.
  return -y_m * y_m / (rho + std::sqrt((rho - y_m) * (rho + y_m)));
}

double head_top_slope(const JointParams& joint, double y_m) {
  if (joint.rail_profile == RailProfile::measured) return joint.measured_head->slope(y_m);
  if (joint.rail_profile == RailProfile::en_60e1) {
    const Arc& a = arc_at(std::abs(y_m));
    const double u = std::abs(y_m) - a.centre_y_m;
    return -std::copysign(u / std::sqrt((a.radius_m - u) * (a.radius_m + u)), y_m);
  }
  if (has_flat_head(joint)) return 0.0;
  const double rho = joint.crown_radius_m;
  return -y_m / std::sqrt((rho - y_m) * (rho + y_m));
}

double head_profile_half_width_m(const JointParams& joint) {
  // The standard's 72 mm head: the 13 mm arc reaches the 1:20 side 0.2 um
  // inside it (35.9998 mm) and goes on to 36.016 mm, so the whole width is on it.
  if (joint.rail_profile == RailProfile::en_60e1) return 0.036;
  if (joint.rail_profile == RailProfile::measured) {
    return std::min(-joint.measured_head->y_min_m(), joint.measured_head->y_max_m());
  }
  return std::numeric_limits<double>::infinity();
}

}  // namespace railjoint
