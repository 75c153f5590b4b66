#pragma once
// Hertz's law of the wheel-rail contact as track dynamics codes use it: the
// normal force grows as the penetration to the power 3/2,
//   F = (delta / G)^(3/2),  delta = G F^(2/3),
// with G [m/N^(2/3)] lumping the radii and the steels' elastic constants.
// Commonly quoted for a new wheel of radius R (Jenkins et al. 1974 and the
// track-dynamics literature after them, e.g. Zhai, "Vehicle-Track Coupled
// Dynamics", 2020, section 2.4): G = 3.86 R^-0.115 1e-8 (R in m); 4.57
// R^-0.149 1e-8 for a worn one. Dissipation in Hunt and Crossley's form (1975):
//   F = K delta^(3/2) (1 + alpha delta_dot / delta_dot_0),
// delta_dot_0 the rate at which the contact closed when it was made, alpha
// chosen so an isolated impact's coefficient of restitution is exactly e
// (hunt_crossley_damping_factor); the force never pulls (clamped at 0).
// SI.

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

/// The smallest restitution the law resolves: a rebound of 1e-4 of the
/// impact speed, plastic to well within the jumps' 1e-3 (a smaller e is
/// taken as this; e = 0 exactly would need an infinite damping factor).
inline constexpr double kSmallestRestitution = 1e-4;

/// Hunt and Crossley's damping factor alpha for a coefficient of restitution
/// e: the force K delta^(3/2) (1 + alpha d(delta)/dt / v0) of an isolated
/// impact at v0 rebounds at exactly e v0. The rebound depends on alpha alone
/// (scaled, X'' = -X^(3/2) max(0, 1 + alpha X'), X(0) = 0, X'(0) = 1), so
/// alpha(e) is that problem solved for alpha (hertz_law.cpp). Hunt and
/// Crossley's own 1.5 (1 - e) is its first term near e = 1 (at e = 0.95
/// within 2 %); at e = 0 it rebounds at 0.49 v0, not 0. Above alpha ~ 1 the
/// force vanishes during the rebound at X' = -1 / alpha, so e = 1 / alpha.
double hunt_crossley_damping_factor(double restitution);

/// The rebound of that scaled impact for a damping factor alpha [-].
double hunt_crossley_restitution(double damping_factor);

/// Hunt and Crossley's force [N]: `closing_rate_m_per_s` = d delta / dt now,
/// `impact_rate_m_per_s` > 0 the rate when the contact was made; never < 0.
/// A factor of 0 or an impact rate of 0 (a contact made at rest) is pure Hertz.
inline double hunt_crossley_force_N(double hertz_constant_m_per_N2_3, double damping_factor, double penetration_m,
                                    double closing_rate_m_per_s, double impact_rate_m_per_s) {
  const double elastic = hertz_force_N(hertz_constant_m_per_N2_3, penetration_m);
  if (!(damping_factor > 0.0) || !(impact_rate_m_per_s > 0.0)) return elastic;
  const double factor = 1.0 + damping_factor * closing_rate_m_per_s / impact_rate_m_per_s;
  return std::max(0.0, elastic * factor);
}

}  // namespace railjoint
