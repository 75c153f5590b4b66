#pragma once
// The classic estimate the compliant simulation's peak force is compared
// with: the P1 force of a dipped rail joint (Jenkins, Stephenson, Clayton,
// Morland and Lyon, "The effect of track and vehicle parameters on
// wheel/rail vertical dynamic forces", Railway Engineering Journal 3(1),
// 1974, pp. 2-16; bibliographic record TRID 00054692,
// https://trid.trb.org/view.aspx?id=19226; P1/P2 restated e.g. by Mandal,
// Dhanasekar and Sun, "Impact forces at dipped rail joints", Proc. IMechE
// Part F, doi:10.1177/0954409714537816). Pure functions, SI.
//
// P1 is the first, high-frequency force peak when a wheel meets a joint
// whose two rail ends make a total dip angle 2 alpha: the wheel's path turns
// by 2 alpha, so the unsprung mass m_u and the rail's effective mass m_e
// close on each other at 2 alpha v through the linearised Hertzian contact
// spring k_H. A linear spring between two free masses closing at u reaches
// u sqrt(k_H mu) above its static force, mu = m_u m_e / (m_u + m_e) the
// reduced mass, hence
//   P1 = P0 + 2 alpha v sqrt(k_H m_e / (1 + m_e / m_u)).
// The thesis's beta is the angle between the two rail ends, so 2 alpha = beta
// (the jump of the vertical velocity is 2 v tan(beta/2) ~ beta v).
//
// Our simulation has a rigid, immovable rail: m_e -> infinity, mu -> m_u = M,
//   P1_rigid = P0 + 2 alpha v sqrt(k_H M),
// an upper bound of Jenkins's value (real track mass takes part of the blow).

#include <cmath>
#include <limits>
#include <numbers>

namespace railjoint {

/// Jenkins et al.'s P1 [N]. `effective_track_mass_kg` may be +infinity (rigid
/// track, the simulation's case). `total_dip_angle_rad` = 2 alpha = beta.
inline double jenkins_p1_force_N(double static_load_N, double total_dip_angle_rad, double speed_m_per_s,
                                 double hertz_stiffness_N_per_m, double unsprung_mass_kg,
                                 double effective_track_mass_kg) {
  const double reduced_mass_kg = std::isinf(effective_track_mass_kg)
                                     ? unsprung_mass_kg
                                     : effective_track_mass_kg / (1.0 + effective_track_mass_kg / unsprung_mass_kg);
  return static_load_N + total_dip_angle_rad * speed_m_per_s * std::sqrt(hertz_stiffness_N_per_m * reduced_mass_kg);
}

/// Jenkins et al.'s P2 [N], in the form the track literature quotes it:
///   P2 = P0 + 2 alpha V sqrt(m_u / (m_u + m_T))
///             [1 - C_T pi / (4 sqrt(K_T (m_u + m_T)))] sqrt(K_T m_u).
/// The low-frequency peak of wheel and track mass m_u + m_T on the track's
/// stiffness K_T: the undamped mode closing at 2 alpha V peaks at
/// 2 alpha V sqrt(K_T m_u^2 / (m_u + m_T)) a quarter period later, and the
/// bracket is the first-order loss of that quarter period to the damping
/// C_T (a decay of zeta pi / 2 with zeta = C_T / (2 sqrt(K_T (m_u + m_T)))).
/// A public calculator codes the bracket as 1 - C_T pi / sqrt(K_T m_T), which
/// has no quarter period and the wrong mass; tests/sim/jenkins_forces_test.cpp
/// holds both numbers.
inline double jenkins_p2_force_N(double static_load_N, double total_dip_angle_rad, double speed_m_per_s,
                                 double unsprung_mass_kg, double track_mass_kg, double track_stiffness_N_per_m,
                                 double track_damping_N_s_per_m) {
  const double m = unsprung_mass_kg + track_mass_kg;
  const double damping_loss = track_damping_N_s_per_m * std::numbers::pi / (4.0 * std::sqrt(track_stiffness_N_per_m * m));
  return static_load_N + total_dip_angle_rad * speed_m_per_s * std::sqrt(unsprung_mass_kg / m) * (1.0 - damping_loss) *
                             std::sqrt(track_stiffness_N_per_m * unsprung_mass_kg);
}

/// Jenkins et al.'s P2 [N] with the damping bracket a public Python
/// calculator codes, 1 - C_T pi / sqrt(K_T m_T) (its worked example gives
/// 125,408.8 N against 136,296.8 N from jenkins_p2_force_N; tests/sim/
/// jenkins_forces_test.cpp). Given beside the default for comparison only:
/// it is not the first-order quarter-period loss (docs/forces.md, "Jenkins et al.").
inline double jenkins_p2_calculator_form_N(double static_load_N, double total_dip_angle_rad, double speed_m_per_s,
                                           double unsprung_mass_kg, double track_mass_kg,
                                           double track_stiffness_N_per_m, double track_damping_N_s_per_m) {
  const double m = unsprung_mass_kg + track_mass_kg;
  const double damping_loss = track_damping_N_s_per_m * std::numbers::pi / std::sqrt(track_stiffness_N_per_m * track_mass_kg);
  return static_load_N + total_dip_angle_rad * speed_m_per_s * std::sqrt(unsprung_mass_kg / m) * (1.0 - damping_loss) *
                             std::sqrt(track_stiffness_N_per_m * unsprung_mass_kg);
}

/// Same with a given velocity change instead of 2 alpha v [N]: P0 + dv sqrt(k M) for
/// a rigid track. The simulation's exact kinematic jump gives dv = Delta p / M.
inline double rigid_track_peak_force_N(double static_load_N, double velocity_change_m_per_s,
                                       double hertz_stiffness_N_per_m, double mass_kg) {
  return static_load_N + velocity_change_m_per_s * std::sqrt(hertz_stiffness_N_per_m * mass_kg);
}

/// Elastic constants of wheel and rail steel (both bodies) for the Hertz stiffness.
struct HertzContact {
  double youngs_modulus_Pa = 210e9;
  double poisson_ratio = 0.3;
  double wheel_radius_m = 0.475;       ///< rolling radius: curvature in the x-z plane
  double rail_crown_radius_m = 0.3;    ///< transverse radius of the rail head (UIC 60: 300 mm crown)
};

/// Hertz approach of two bodies under a normal load P [m], with the
/// equivalent-radius approximation for a nearly circular contact (Johnson,
/// Contact Mechanics, Cambridge University Press 1985, sections 4.1-4.2):
///   delta = (9 P^2 / (16 E*^2 R_e))^(1/3),  R_e = sqrt(R' R''),
///   1/E* = 2 (1 - nu^2) / E for two bodies of the same steel,
/// R' = the wheel radius (the rail is straight along x), R'' = the rail crown
/// radius (the tread is taken flat across). R'/R'' = 1.6 keeps the contact
/// ellipse near circular, where the approximation is within a few %.
inline double hertz_approach_m(const HertzContact& c, double load_N) {
  const double e_star = c.youngs_modulus_Pa / (2.0 * (1.0 - c.poisson_ratio * c.poisson_ratio));
  const double r_e = std::sqrt(c.wheel_radius_m * c.rail_crown_radius_m);
  return std::cbrt(9.0 * load_N * load_N / (16.0 * e_star * e_star * r_e));
}

/// Linearised Hertzian stiffness at the static load P0 [N/m]: the tangent
/// dP/d delta = (3/2) P0 / delta(P0) of P ~ delta^(3/2).
inline double linearised_hertz_stiffness_N_per_m(const HertzContact& c, double static_load_N) {
  return 1.5 * static_load_N / hertz_approach_m(c, static_load_N);
}

}  // namespace railjoint
