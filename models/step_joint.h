#pragma once
// The classic step in vertical geometry (thesis section 3.2.2): a wheel of
// radius R meets a step of height u0 and pivots about its edge. The worked
// example the inclined joint is built on.

namespace railjoint {

/// Geometry of the two-point contact at a step up of height u0 (0 < u0 < R).
struct StepContact {
  double a_m = 0.0;          ///< horizontal distance edge - wheel centre line, exact sqrt(2 R u0 - u0^2) [m]
  double a_large_R_m = 0.0;  ///< same for R >> u0: sqrt(2 R u0) [m]
  double alpha_rad = 0.0;    ///< cos(alpha) = (R - u0) / R [rad]
};

StepContact step_contact(double radius_m, double step_height_m);

/// Vertical velocity right after the two-point contact, horizontal speed v held [m/s]:
/// exact v tan(alpha) = v a / (R - u0).
double step_zdot_after_exact(double radius_m, double step_height_m, double speed_m_per_s);
/// Thesis eq. 3.6 as printed: v sqrt(2 R u0) / sqrt(R^2 - 2 R u0) (drops the u0^2 terms).
double step_zdot_after_thesis(double radius_m, double step_height_m, double speed_m_per_s);
/// Thesis eq. 3.6 for R >> u0: v sqrt(2 u0 / R).
double step_zdot_after_small(double radius_m, double step_height_m, double speed_m_per_s);

/// Centre height z(t) [m] relative to the approach level, t = 0 at the two-point
/// contact, for the exact path (pivot about the edge until t1 = a / v, then flat at u0).
double step_centre_height_m(double radius_m, double step_height_m, double speed_m_per_s, double t_s);
/// Its time derivative zdot(t) [m/s] (right-continuous at t = 0).
double step_centre_zdot_m_per_s(double radius_m, double step_height_m, double speed_m_per_s, double t_s);

}  // namespace railjoint
