#include "sim/timoshenko_rail.h"

#include <algorithm>
#include <cmath>

namespace railjoint::timoshenko_rail {

void add_forces(const Springs& springs, const std::vector<double>& w, const std::vector<double>& psi,
                std::vector<double>& f, std::vector<double>& torque) {
  const double h = springs.node_spacing_m;
  for (std::size_t s = 0; s + 1 < w.size(); ++s) {
    // The segment's shear force Q = kappa G A gamma: dU/dw_s+1 = Q, dU/dw_s = -Q, dU/dpsi_s = -Q h.
    const double shear_N = springs.shear_stiffness_N * ((w[s + 1] - w[s]) / h - psi[s]);
    f[s] += shear_N;
    f[s + 1] -= shear_N;
    torque[s] += shear_N * h;
  }
  for (std::size_t i = 1; i + 1 < w.size(); ++i) {
    // The bending moment at node i: dU/dpsi_i = M, dU/dpsi_i-1 = -M.
    const double moment_N_m = springs.bending_N_m_per_rad[i] * (psi[i] - psi[i - 1]);
    torque[i - 1] += moment_N_m;
    torque[i] -= moment_N_m;
  }
}

double strain_energy_J(const Springs& springs, const std::vector<double>& w, const std::vector<double>& psi) {
  const double h = springs.node_spacing_m;
  double u = 0.0;
  for (std::size_t s = 0; s + 1 < w.size(); ++s) {
    const double gamma = (w[s + 1] - w[s]) / h - psi[s];
    u += 0.5 * springs.shear_stiffness_N * h * gamma * gamma;
  }
  for (std::size_t i = 1; i + 1 < w.size(); ++i) {
    const double turn = psi[i] - psi[i - 1];
    u += 0.5 * springs.bending_N_m_per_rad[i] * turn * turn;
  }
  return u;
}

void add_stiffness(const Springs& springs, std::vector<Eigen::Triplet<double>>& entries) {
  const double h = springs.node_spacing_m;
  const Eigen::Index n = static_cast<Eigen::Index>(springs.bending_N_m_per_rad.size());
  for (Eigen::Index s = 0; s + 1 < n; ++s) {
    // gamma = g . (w_s, psi_s, w_s+1): kappa G A h g g^T.
    const Eigen::Index dof[3] = {2 * s, 2 * s + 1, 2 * s + 2};
    const double g[3] = {-1.0 / h, -1.0, 1.0 / h};
    const double k = springs.shear_stiffness_N * h;
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) entries.emplace_back(dof[a], dof[b], k * g[a] * g[b]);
  }
  for (Eigen::Index i = 1; i + 1 < n; ++i) {
    // psi_i - psi_i-1: the turn at node i.
    const double k = springs.bending_N_m_per_rad[static_cast<std::size_t>(i)];
    const Eigen::Index l = 2 * i - 1, r = 2 * i + 1;
    entries.emplace_back(l, l, k);
    entries.emplace_back(r, r, k);
    entries.emplace_back(l, r, -k);
    entries.emplace_back(r, l, -k);
  }
}

double highest_frequency_bound_rad_per_s(double EI, double mu, double kGA, double rho_I, double h) {
  // Rows of M^-1/2 K M^-1/2, absolute values summed. A node: two shear
  // springs kGA / h on it and its neighbours, kGA to each segment beside it.
  // A segment: kGA h and two bending springs EI / h on it, EI / h to each
  // neighbour, kGA to each of its nodes.
  const double node_mass = mu * h, segment_inertia = rho_I * h;
  const double cross = 2.0 * kGA / std::sqrt(node_mass * segment_inertia);
  const double node_row = 4.0 * kGA / h / node_mass + cross;
  const double segment_row = (kGA * h + 4.0 * EI / h) / segment_inertia + cross;
  return std::sqrt(std::max(node_row, segment_row));
}

}  // namespace railjoint::timoshenko_rail
