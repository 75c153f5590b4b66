#include "models/contact_curvatures.h"

#include <cmath>

#include "models/rail_head.h"
#include "models/rail_top.h"
#include "models/wheel_tread.h"

namespace railjoint {

namespace {

template <class Slope>
double second_derivative(Slope slope, double at) {
  return (slope(at + kCurvatureStep_m) - slope(at - kCurvatureStep_m)) / (2.0 * kCurvatureStep_m);
}

// Convex-positive normal curvature of a graph with slope s and second
// derivative s' bulging towards the other body: -s' / (1 + s^2)^(3/2).
double graph_curvature_per_m(double slope, double second) { return -second / std::pow(1.0 + slope * slope, 1.5); }

}  // namespace

ContactCurvatures contact_curvatures_at(const JointParams& joint, const WheelParams& wheel, int rail, double x_m,
                                        double y_m) {
  ContactCurvatures k;
  const double r = tread_radius_m(wheel, y_m);
  const double r1 = tread_radius_slope(wheel, y_m);
  k.wheel_along_x_per_m = 1.0 / (r * std::sqrt(1.0 + r1 * r1));
  // The wheel's surface z = c_z - r(y) bulges down where r'' < 0.
  k.wheel_across_y_per_m =
      graph_curvature_per_m(r1, second_derivative([&](double y) { return tread_radius_slope(wheel, y); }, y_m));
  k.rail_across_y_per_m = graph_curvature_per_m(
      head_top_slope(joint, y_m), second_derivative([&](double y) { return head_top_slope(joint, y); }, y_m));
  k.rail_along_x_per_m = graph_curvature_per_m(
      rail_surface_slope(joint, rail, x_m), second_derivative([&](double x) { return rail_surface_slope(joint, rail, x); }, x_m));
  return k;
}

}  // namespace railjoint
