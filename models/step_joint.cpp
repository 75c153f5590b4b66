#include "models/step_joint.h"

#include <cassert>
#include <cmath>

namespace railjoint {

StepContact step_contact(double radius_m, double step_height_m) {
  assert(step_height_m >= 0.0 && step_height_m < radius_m);
  const double R = radius_m;
  const double u0 = step_height_m;
  StepContact contact;
  contact.a_m = std::sqrt(2.0 * R * u0 - u0 * u0);
  contact.a_large_R_m = std::sqrt(2.0 * R * u0);
  contact.alpha_rad = std::acos((R - u0) / R);
  return contact;
}

double step_zdot_after_exact(double radius_m, double step_height_m, double speed_m_per_s) {
  const StepContact contact = step_contact(radius_m, step_height_m);
  return speed_m_per_s * contact.a_m / (radius_m - step_height_m);
}

double step_zdot_after_thesis(double radius_m, double step_height_m, double speed_m_per_s) {
  const double R = radius_m;
  const double u0 = step_height_m;
  // Eq. 3.6 is only defined while R^2 > 2 R u0 (u0 < R/2); beyond it the
  // printed form has no real value and the caller gets NaN, not a made-up number.
  return speed_m_per_s * std::sqrt(2.0 * R * u0) / std::sqrt(R * R - 2.0 * R * u0);
}

double step_zdot_after_small(double radius_m, double step_height_m, double speed_m_per_s) {
  return speed_m_per_s * std::sqrt(2.0 * step_height_m / radius_m);
}

double step_centre_height_m(double radius_m, double step_height_m, double speed_m_per_s, double t_s) {
  if (t_s < 0.0) return 0.0;
  const double a = step_contact(radius_m, step_height_m).a_m;
  const double x = speed_m_per_s * t_s;
  if (x >= a) return step_height_m;
  // Pivot about the edge at (a, u0 - R) relative to the centre at contact.
  return -radius_m + step_height_m + std::sqrt(radius_m * radius_m - (a - x) * (a - x));
}

double step_centre_zdot_m_per_s(double radius_m, double step_height_m, double speed_m_per_s, double t_s) {
  if (t_s < 0.0) return 0.0;
  const double a = step_contact(radius_m, step_height_m).a_m;
  const double x = speed_m_per_s * t_s;
  if (x >= a) return 0.0;
  return speed_m_per_s * (a - x) / std::sqrt(radius_m * radius_m - (a - x) * (a - x));
}

}  // namespace railjoint
