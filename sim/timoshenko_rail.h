#pragma once
// The discrete track's rail as a Timoshenko beam (track.beam =
// "timoshenko"): the rigid finite element method's chain (Kruszewski's RFEM;
// Wittbrodt, Adamiec-Wojcik and Wojciech, "Dynamics of Flexible Multibody
// Systems: Rigid Finite Element Method", 2006) with shear springs. Nodes
// every h carry the deflection w and the mass mu h, as the Euler chain's;
// the segment between nodes s and s + 1 turns by its own psi_s, carries the
// rotary inertia rho I h and a shear spring on
// gamma_s = (w_s+1 - w_s) / h - psi_s (energy kappa G A h gamma^2 / 2);
// node i's bending spring k_i (EI / h, the joint's own) joins the segments
// beside it (energy k_i (psi_i - psi_i-1)^2 / 2). As kappa G A grows, psi_s
// tends to the chord's slope and the bending energy to the Euler chain's
// k_i ((w_i+1 - 2 w_i + w_i-1) / h)^2 / 2 (discrete_track.h): the two meet in
// that limit, so the difference between them is the shear and the rotary
// inertia alone, on the same nodes and masses. Its shear is exact in
// statics (the segments' shear forces are the beam's); its bending, as the
// Euler chain's, is second order in h (tests/sim/timoshenko_rail_test.cpp).
// Eigen only.

#include <vector>

#include <Eigen/SparseCore>

namespace railjoint::timoshenko_rail {

/// The chain's springs: bending spring per node [N m/rad] (0 at free ends),
/// kappa G A [N], node spacing h [m]. n nodes, n - 1 segments.
struct Springs {
  const std::vector<double>& bending_N_m_per_rad;
  double shear_stiffness_N;
  double node_spacing_m;
};

/// Adds -dU/dw to `force_N` (per node) and -dU/dpsi to `torque_N_m` (per
/// segment) of the chain's strain energy U at (w, psi).
void add_forces(const Springs& springs, const std::vector<double>& w_m, const std::vector<double>& psi_rad,
                std::vector<double>& force_N, std::vector<double>& torque_N_m);

/// U at (w, psi) [J].
double strain_energy_J(const Springs& springs, const std::vector<double>& w_m, const std::vector<double>& psi_rad);

/// The stiffness matrix's entries (summed where they repeat), the degrees
/// of freedom interleaved so the matrix is banded: w_i at 2 i, psi_s at 2 s + 1.
void add_stiffness(const Springs& springs, std::vector<Eigen::Triplet<double>>& entries);

/// An upper bound on the chain's highest angular frequency with node mass
/// mu h and segment inertia rho I h [rad/s]: Gershgorin's on
/// M^-1/2 K M^-1/2, of an interior node and segment with bending springs
/// EI / h (the largest: the joint's is softer). Euler's chain gives its
/// exact 4 / h^2 sqrt(EI / mu) the same way.
double highest_frequency_bound_rad_per_s(double bending_stiffness_N_m2, double mass_per_length_kg_per_m,
                                         double shear_stiffness_N, double rotary_inertia_kg_m, double h_m);

}  // namespace railjoint::timoshenko_rail
