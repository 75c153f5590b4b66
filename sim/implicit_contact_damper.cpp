#include "sim/implicit_contact_damper.h"

#include <algorithm>

namespace railjoint {

DampedContactForces solve_damped_contacts(const std::array<DampedContact, 2>& contacts,
                                          const std::array<bool, 2>& bearing,
                                          const std::array<std::array<double, 2>, 2>& slowing_m_per_s_per_N) {
  const auto& W = slowing_m_per_s_per_N;
  // The closing rate at k with the forces F (absent contacts press 0).
  const auto closing_with = [&](std::size_t k, const std::array<double, 2>& F) {
    double slowed = 0.0;
    for (std::size_t j = 0; j < 2; ++j) {
      if (!bearing[j]) continue;
      slowed += W[k][j] * (contacts[j].last_pressed_N - contacts[j].normal_z * F[j]);
    }
    return contacts[k].closing_m_per_s + contacts[k].normal_z * slowed;
  };
  // Hunt and Crossley's force at k, unclamped, with the forces F.
  const auto law_with = [&](std::size_t k, const std::array<double, 2>& F) {
    return contacts[k].elastic_N * (1.0 + contacts[k].per_rate_s_per_m * closing_with(k, F));
  };
  // Solves the law as equalities on the contacts of `on` (linear in F:
  // F_k + E_k p_k n_k sum_j W_kj n_j F_j = E_k (1 + p_k (r_k + n_k sum_j W_kj P_j))),
  // the others at 0.
  const auto solve_on = [&](const std::array<bool, 2>& on) {
    std::array<double, 2> F{};
    const std::array<double, 2> zero{};
    double A[2][2] = {}, q[2] = {};
    for (std::size_t k = 0; k < 2; ++k) {
      if (!on[k]) continue;
      const double gain = contacts[k].elastic_N * contacts[k].per_rate_s_per_m * contacts[k].normal_z;
      q[k] = law_with(k, zero);
      for (std::size_t j = 0; j < 2; ++j) A[k][j] = (k == j ? 1.0 : 0.0) + (on[j] ? gain * W[k][j] * contacts[j].normal_z : 0.0);
    }
    if (on[0] && on[1]) {
      const double det = A[0][0] * A[1][1] - A[0][1] * A[1][0];
      F[0] = (q[0] * A[1][1] - A[0][1] * q[1]) / det;
      F[1] = (A[0][0] * q[1] - A[1][0] * q[0]) / det;
    } else {
      for (std::size_t k = 0; k < 2; ++k)
        if (on[k]) F[k] = q[k] / A[k][k];
    }
    return F;
  };
  // The force never pulls: the first set of contacts bearing with F >= 0
  // whose others' law asks for no push (I + diag(E p n) W diag(n) has
  // positive eigenvalues, W a mobility and so positive semi-definite: one
  // such set exists).
  const std::array<std::array<bool, 2>, 4> sets = {
      {{bearing[0], bearing[1]}, {bearing[0], false}, {false, bearing[1]}, {false, false}}};
  std::array<double, 2> F = solve_on(bearing);  // clamped below if no set holds (round-off)
  for (const std::array<bool, 2>& on : sets) {
    const std::array<double, 2> trial = solve_on(on);
    bool holds = true;
    for (std::size_t k = 0; k < 2; ++k) {
      if (!bearing[k]) continue;
      holds = holds && (on[k] ? trial[k] >= 0.0 : law_with(k, trial) <= 0.0);
    }
    if (holds) {
      F = trial;
      break;
    }
  }
  DampedContactForces out;
  for (std::size_t k = 0; k < 2; ++k) out.force_N[k] = bearing[k] ? std::max(0.0, F[k]) : 0.0;
  for (std::size_t k = 0; k < 2; ++k) out.closing_m_per_s[k] = bearing[k] ? closing_with(k, out.force_N) : 0.0;
  return out;
}

}  // namespace railjoint
