#pragma once
// Hertz's law of the wheel-rail contact as track dynamics codes use it: the
// normal force grows as the penetration to the power 3/2,
//   F = (delta / G)^(3/2),  delta = G F^(2/3),
// with G [m/N^(2/3)] lumping the radii and the steels' elastic constants.
// Commonly quoted for a new wheel of radius R (Jenkins et al. 1974 and the
// track-dynamics literature after them, e.g. Zhai, "Vehicle-Track Coupled
// Dynamics", 2020, section 2.4): G = 3.86 R^-0.115 1e-8 (R in m); 4.57
// R^-0.149 1e-8 for a worn one. Dissipation by Hunt and Crossley (1975):
//   F = K delta^(3/2) (1 + (3/2)(1 - e) delta_dot / delta_dot_0),
// delta_dot_0 the rate at which the contact closed when it was made, e the
// coefficient of restitution; the force never pulls (clamped at 0).
// Pure functions, SI.

#include <algorithm>
#include <cmath>

namespace railjoint {

/// The commonly quoted Hertz constant of a new wheel of radius R [m/N^(2/3)].
inline double default_hertz_constant_m_per_N2_3(double wheel_radius_m) {
  return 3.86e-8 * std::pow(wheel_radius_m, -0.115);
}

/// Penetration under a normal force F >= 0 [m].
inline double hertz_approach_m(double hertz_constant_m_per_N2_3, double force_N) {
  return hertz_constant_m_per_N2_3 * std::cbrt(force_N * force_N);
}

/// Elastic force at penetration delta (0 when delta <= 0) [N].
inline double hertz_force_N(double hertz_constant_m_per_N2_3, double penetration_m) {
  if (!(penetration_m > 0.0)) return 0.0;
  const double ratio = penetration_m / hertz_constant_m_per_N2_3;
  return ratio * std::sqrt(ratio);
}

/// Elastic energy stored at penetration delta: the integral of the force,
/// (2/5) delta^(5/2) / G^(3/2) [J].
inline double hertz_energy_J(double hertz_constant_m_per_N2_3, double penetration_m) {
  return penetration_m > 0.0 ? 0.4 * penetration_m * hertz_force_N(hertz_constant_m_per_N2_3, penetration_m) : 0.0;
}

/// Tangent stiffness dF/d delta at the force P0: (3/2) P0^(1/3) / G [N/m]
/// (K_H of Jenkins's P1 formula).
inline double linearised_hertz_stiffness_N_per_m(double hertz_constant_m_per_N2_3, double force_N) {
  return 1.5 * std::cbrt(force_N) / hertz_constant_m_per_N2_3;
}

/// Hunt and Crossley's force [N]: `closing_rate_m_per_s` = d delta / dt now,
/// `impact_rate_m_per_s` > 0 the rate when the contact was made; never < 0.
/// e = 1 or an impact rate of 0 (a contact that was made at rest) is pure Hertz.
inline double hunt_crossley_force_N(double hertz_constant_m_per_N2_3, double restitution, double penetration_m,
                                    double closing_rate_m_per_s, double impact_rate_m_per_s) {
  const double elastic = hertz_force_N(hertz_constant_m_per_N2_3, penetration_m);
  if (restitution >= 1.0 || !(impact_rate_m_per_s > 0.0)) return elastic;
  const double factor = 1.0 + 1.5 * (1.0 - restitution) * closing_rate_m_per_s / impact_rate_m_per_s;
  return std::max(0.0, elastic * factor);
}

}  // namespace railjoint
