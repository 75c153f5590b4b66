#pragma once
// The classic step in vertical geometry (thesis section 3.2.2): a wheel of
// radius R meets a step of height u0 and pivots about its edge. The worked
// example the inclined joint is built on. These are the thesis's forms; the
// exact jump comes from the profile solve (models/impact_prediction.h).

namespace railjoint {

/// Horizontal distance edge - wheel centre line at the two-point contact for
/// R >> u0 (0 <= u0 < R): sqrt(2 R u0), where the exact one is sqrt(2 R u0 - u0^2) [m].
double step_edge_distance_large_R_m(double radius_m, double step_height_m);

/// Thesis eq. 3.6 as printed: v sqrt(2 R u0) / sqrt(R^2 - 2 R u0) (drops the u0^2 terms) [m/s].
double step_zdot_after_thesis(double radius_m, double step_height_m, double speed_m_per_s);

}  // namespace railjoint
