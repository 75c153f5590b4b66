#pragma once
// Hunt and Crossley's damper taken implicitly over a force run's step
// (elastic_crossing_run.cpp). A contact's force F = E (1 + p r), E Hertz's
// elastic force (its merged-patch share of it), p = alpha / v_impact, r the
// rate at which Hertz's approach closes at the step's end. Velocity Verlet
// (vertical_mass.h) predicts that rate with the last step's accelerations,
// so the damper acts on the bodies under it one step late: a pure damper
// c = p E on a mass m survives that only for c dt / m below about 1, which
// a strongly damped contact on rail nodes of 4.5 kg, or one made again at a
// small impact rate (p huge), is not (docs/forces.md, "The step"). The
// rate at the step's end is linear in the step's own forces: each newton
// pressed beyond the last step's force slows the closing at contact k by
//   W_kj = dt/2 (1/M + mu(x_k, x_j)) + c(x_k, x_j) / dt   [m/s per N]
// (the second half kick of the wheel, M, and of the rail under both
// contacts, mu the track's rate at x_k per unit impulse at x_j; and a
// Timoshenko rail's local give c under the force, read one step late),
// times the normals' z. So the step's forces solve
//   F_k = max(0, E_k (1 + p_k (r_k + n_k sum_j W_kj (P_j - n_j F_j)))),
// r_k the predicted rate, P_j the vertical force contact j pressed in the
// last step: one wheel's two contacts, a 2 x 2 linear system with F >= 0.
// A pure damper then steps as the trapezoidal rule, (1 - c dt / 2m) /
// (1 + c dt / 2m), stable at any c. Undamped contacts (p 0) keep F = E.
// Pure math, SI.

#include <array>

namespace railjoint {

/// One bearing contact of a wheel at the step's end.
struct DampedContact {
  double elastic_N = 0.0;         ///< E: Hertz's force (its share) at the penetration
  double per_rate_s_per_m = 0.0;  ///< p = alpha / v_impact; 0 undamped
  double closing_m_per_s = 0.0;   ///< r: the closing rate the predicted velocities give
  double normal_z = 1.0;          ///< n: the contact normal's z (the force presses n F down on the rail)
  double last_pressed_N = 0.0;    ///< P: the vertical force it pressed in the last step (0 if none)
};

/// The step's forces and the closing rates they leave [N, m/s].
struct DampedContactForces {
  std::array<double, 2> force_N{};
  std::array<double, 2> closing_m_per_s{};
};

/// Solves the system above for up to two contacts (`bearing` says which
/// take part; the others get 0). `slowing_m_per_s_per_N[k][j]` is W_kj.
DampedContactForces solve_damped_contacts(const std::array<DampedContact, 2>& contacts,
                                          const std::array<bool, 2>& bearing,
                                          const std::array<std::array<double, 2>, 2>& slowing_m_per_s_per_N);

}  // namespace railjoint
