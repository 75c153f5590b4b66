#pragma once
// An independent reference for a force run on the discrete track, written in
// the tests (no sim/ code): the rail as cubic Hermite (Euler-Bernoulli) beam
// elements on the same discrete supports, integrated by Newmark's average
// acceleration rule (implicit, unconditionally stable, second order) with a
// fine step, the wheel's Hertz contact solved within each step by Newton's
// method.
//
// What differs from sim/discrete_track.h on purpose:
// - the rail between nodes is the beam equation's own cubic (exact between
//   point forces in statics), where the sim has rigid links and rotational
//   springs (a central fourth difference) read through an interpolation;
// - the hinge is exact: the joint node has one deflection and two rotations,
//   one per rail end, joined by the joint's rotational spring (absent: one
//   rotation, continuous rail);
// - consistent mass, implicit integration, its own start (far out, see below).
//
// The model. Nodes every s / elements_per_bay over [-L, L] (whole bays), the
// joint at x = 0 on a node midway between sleepers at +-(k + 1/2) s. Each
// sleeper: a pad (k_p, c_p) from the rail node above it to the sleeper mass,
// ballast (k_b, c_b) to the ground. Displacements from the unloaded track
// under its own weight (the masses' weights rest on the springs and change
// nothing in the motion). The wheel (mass M, radius R) moves at x = x0 + v t,
// vertically under its weight and the static wheel load W0 (together W) and
// the contact forces. The rail tops are the dip's lines z = -t x (incoming,
// x <= 0) and z = +t x (outgoing, x >= 0), t = tan(beta / 2), moved by the
// beam's deflection; the wheel's circle touches each at the foot of the
// perpendicular from its centre, or at the rail's end corner (0, w(0)) when
// that foot lies beyond it. Penetration delta = R - distance, normal force
// (delta / G)^(3/2) (pure Hertz: restitution 1; the two rail ends coupled
// where both bear, spanning_contact_reference.h), whose vertical part loads
// the beam at the foot through the element's shape functions (the beam on
// the rail's own side of the hinge).
//
// The start: the track in its static state under W at the start's contact,
// moving as that state does when the load moves on at v, the wheel in its
// static state on the incoming slope. The residual (the moving load's
// inertia) rings down long before the joint when the start is far out: the
// tests check a 1.5x further start changes nothing.

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include "tests/sim/spanning_contact_reference.h"

namespace railjoint::testing_reference {

struct HermiteBeamCrossing {
  // Rail and supports (the discrete track's defaults: 60E1 on sleepers every 0.6 m).
  double bending_stiffness_N_m2 = 6.38e6;
  double mass_per_length_kg_per_m = 60.2;
  double sleeper_spacing_m = 0.6;
  double pad_stiffness = 200e6, pad_damping = 28e3;
  double sleeper_mass_kg = 140.0;
  double ballast_stiffness = 40e6, ballast_damping = 47e3;
  bool hinge = false;            ///< false: continuous rail
  double joint_stiffness = 0.0;  ///< the hinge's rotational spring [N m/rad]
  int elements_per_bay = 8;
  double half_length_m = 8.0;  ///< rounded out to whole bays
  // Wheel and contact.
  double radius_m = 0.475;
  double wheel_mass_kg = 750.0;
  double speed_m_per_s = 50.0;
  double wheel_load_N = 112.5e3;
  double half_dip_slope = 0.015;   ///< tan(beta / 2)
  double hertz_constant = 4.2e-8;  ///< G [m/N^(2/3)]
  double gravity = 9.80665;
  // The run.
  double start_x_m = -3.0;  ///< the wheel centre's x at t = 0
  double end_x_m = 1.0;     ///< the wheel centre's x at the end
  double step_s = 2e-6;
};

struct HermiteBeamRun {
  std::vector<double> time_s;         ///< the step ends (the first sample: the start)
  std::vector<double> wheel_x_m;
  std::vector<double> force_z_N;      ///< the total vertical contact force on the wheel
  std::vector<double> peak_pad_N;     ///< the largest pad (rail-seat) force over the sleepers, compression +
  std::vector<double> peak_ballast_N; ///< the largest ballast force over the sleepers
};

class HermiteBeam {
 public:
  explicit HermiteBeam(const HermiteBeamCrossing& c) : c_(c) {
    const double s = c.sleeper_spacing_m;
    const int bays = std::max(1, static_cast<int>(std::ceil(c.half_length_m / s - 1e-9)));
    h_ = s / c.elements_per_bay;
    nodes_ = 2 * bays * c.elements_per_bay + 1;
    joint_ = bays * c.elements_per_bay;
    x0_ = -bays * s;
    right_theta_ = c.hinge ? 2 * nodes_ : 2 * joint_ + 1;
    beam_dofs_ = 2 * nodes_ + (c.hinge ? 1 : 0);
    for (int b = 0; b < 2 * bays; ++b) sleeper_node_.push_back(b * c.elements_per_bay + c.elements_per_bay / 2);
    dofs_ = beam_dofs_ + static_cast<int>(sleeper_node_.size());
    assemble();
  }

  int node_count() const { return nodes_; }
  double node_x_m(int i) const { return x0_ + i * h_; }

  /// The four element DOFs under x and their Hermite weights for the
  /// deflection at x; `left`: a point at a node belongs to the element on
  /// its left (the incoming rail's side of the hinge).
  void shape(double x_m, bool left, int dof[4], double n[4]) const {
    double position = (x_m - x0_) / h_;
    int e = static_cast<int>(std::floor(position));
    if (left && position == std::floor(position)) e -= 1;
    e = std::clamp(e, 0, nodes_ - 2);
    const double xi = std::clamp(position - e, 0.0, 1.0);
    dof[0] = 2 * e;
    dof[1] = e == joint_ ? right_theta_ : 2 * e + 1;  // the element right of the joint: the right rail's rotation
    dof[2] = 2 * (e + 1);
    dof[3] = 2 * (e + 1) + 1;
    n[0] = 1 - 3 * xi * xi + 2 * xi * xi * xi;
    n[1] = h_ * (xi - 2 * xi * xi + xi * xi * xi);
    n[2] = 3 * xi * xi - 2 * xi * xi * xi;
    n[3] = h_ * (-xi * xi + xi * xi * xi);
  }

  double deflection_m(const Eigen::VectorXd& u, double x_m, bool left) const {
    int dof[4];
    double n[4];
    shape(x_m, left, dof, n);
    double w = 0;
    for (int a = 0; a < 4; ++a) w += n[a] * u(dof[a]);
    return w;
  }

  /// The static state under a downward force at x.
  Eigen::VectorXd static_state(double load_N, double x_m, bool left) const {
    Eigen::VectorXd f = Eigen::VectorXd::Zero(dofs_);
    add_load(f, x_m, left, -load_N);
    return static_.solve(f);
  }

  /// Pad (rail seat) and ballast forces of sleeper j in state (u, v), compression + [N].
  double pad_N(const Eigen::VectorXd& u, const Eigen::VectorXd& v, std::size_t j) const {
    const int r = 2 * sleeper_node_[j], q = beam_dofs_ + static_cast<int>(j);
    return c_.pad_stiffness * (u(q) - u(r)) + c_.pad_damping * (v(q) - v(r));
  }
  double ballast_N(const Eigen::VectorXd& u, const Eigen::VectorXd& v, std::size_t j) const {
    const int q = beam_dofs_ + static_cast<int>(j);
    return -c_.ballast_stiffness * u(q) - c_.ballast_damping * v(q);
  }
  std::size_t sleeper_count() const { return sleeper_node_.size(); }
  double sleeper_x_m(std::size_t j) const { return node_x_m(sleeper_node_[j]); }

  HermiteBeamRun run() const;

 private:
  void add_load(Eigen::VectorXd& f, double x_m, bool left, double force_up_N) const {
    int dof[4];
    double n[4];
    shape(x_m, left, dof, n);
    for (int a = 0; a < 4; ++a) f(dof[a]) += n[a] * force_up_N;
  }

  void assemble() {
    std::vector<Eigen::Triplet<double>> k, m, d;
    const double EI = c_.bending_stiffness_N_m2, mu = c_.mass_per_length_kg_per_m, L = h_;
    const double ke[4][4] = {{12, 6 * L, -12, 6 * L},
                             {6 * L, 4 * L * L, -6 * L, 2 * L * L},
                             {-12, -6 * L, 12, -6 * L},
                             {6 * L, 2 * L * L, -6 * L, 4 * L * L}};
    const double me[4][4] = {{156, 22 * L, 54, -13 * L},
                             {22 * L, 4 * L * L, 13 * L, -3 * L * L},
                             {54, 13 * L, 156, -22 * L},
                             {-13 * L, -3 * L * L, -22 * L, 4 * L * L}};
    for (int e = 0; e + 1 < nodes_; ++e) {
      const int map[4] = {2 * e, e == joint_ ? right_theta_ : 2 * e + 1, 2 * (e + 1), 2 * (e + 1) + 1};
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b) {
          k.emplace_back(map[a], map[b], EI / (L * L * L) * ke[a][b]);
          m.emplace_back(map[a], map[b], mu * L / 420.0 * me[a][b]);
        }
    }
    if (c_.hinge) {
      const int l = 2 * joint_ + 1, r = right_theta_;
      k.emplace_back(l, l, c_.joint_stiffness);
      k.emplace_back(r, r, c_.joint_stiffness);
      k.emplace_back(l, r, -c_.joint_stiffness);
      k.emplace_back(r, l, -c_.joint_stiffness);
    }
    const double series = c_.pad_stiffness * c_.ballast_stiffness / (c_.pad_stiffness + c_.ballast_stiffness);
    std::vector<Eigen::Triplet<double>> ks = k;  // the static stiffness: pad and ballast in series, no sleeper DOF
    for (std::size_t j = 0; j < sleeper_node_.size(); ++j) {
      const int r = 2 * sleeper_node_[j], q = beam_dofs_ + static_cast<int>(j);
      for (auto* list : {&k, &d}) {
        const double kk = list == &k ? c_.pad_stiffness : c_.pad_damping;
        list->emplace_back(r, r, kk);
        list->emplace_back(q, q, kk);
        list->emplace_back(r, q, -kk);
        list->emplace_back(q, r, -kk);
      }
      k.emplace_back(q, q, c_.ballast_stiffness);
      d.emplace_back(q, q, c_.ballast_damping);
      m.emplace_back(q, q, c_.sleeper_mass_kg);
      ks.emplace_back(r, r, series);
      ks.emplace_back(q, q, 1.0);  // the sleeper's DOF: solved apart below
    }
    K_.resize(dofs_, dofs_);
    M_.resize(dofs_, dofs_);
    C_.resize(dofs_, dofs_);
    K_.setFromTriplets(k.begin(), k.end());
    M_.setFromTriplets(m.begin(), m.end());
    C_.setFromTriplets(d.begin(), d.end());
    Eigen::SparseMatrix<double> Ks(dofs_, dofs_);
    Ks.setFromTriplets(ks.begin(), ks.end());
    static_.compute(Ks);
  }

  HermiteBeamCrossing c_;
  double h_ = 0, x0_ = 0;
  int nodes_ = 0, joint_ = 0, right_theta_ = 0, beam_dofs_ = 0, dofs_ = 0;
  std::vector<int> sleeper_node_;
  Eigen::SparseMatrix<double> K_, M_, C_;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> static_;

 public:
  /// The static solution fills the sleepers' DOFs with zero (their row is
  /// the identity); at rest a sleeper sits at k_p / (k_p + k_b) of its rail
  /// node, where pad and ballast carry the same force.
  void settle_sleepers(Eigen::VectorXd& u) const {
    for (std::size_t j = 0; j < sleeper_node_.size(); ++j) {
      u(beam_dofs_ + static_cast<int>(j)) =
          c_.pad_stiffness / (c_.pad_stiffness + c_.ballast_stiffness) * u(2 * sleeper_node_[j]);
    }
  }
  const Eigen::SparseMatrix<double>& stiffness() const { return K_; }
  const Eigen::SparseMatrix<double>& mass() const { return M_; }
  const Eigen::SparseMatrix<double>& damping() const { return C_; }
  int dofs() const { return dofs_; }
};

// One rail's contact with the wheel's circle: where it loads the rail (the
// foot of the perpendicular from the centre (x, z) on the undeflected top line
// z = m x, R / norm m ahead of x: the deflection's slope, ~1e-3, moves it by
// microns; or the rail end's corner at x = 0 when the foot lies beyond it),
// and the vertical force on the wheel with the rail there deflected by w.
inline double rail_foot_x_m(const HermiteBeamCrossing& c, double x, bool incoming) {
  const double t = c.half_dip_slope, norm = std::sqrt(1.0 + t * t);
  const double foot_x = x + (incoming ? -t : t) * c.radius_m / norm;
  return (incoming ? foot_x <= 0.0 : foot_x >= 0.0) ? foot_x : 0.0;
}

inline RailEndTouch rail_touch(const HermiteBeamCrossing& c, double x, double z, double w_foot_m, bool incoming) {
  const double t = c.half_dip_slope, norm = std::sqrt(1.0 + t * t);
  const double m = incoming ? -t : t;
  const double foot_x = x + m * c.radius_m / norm;
  RailEndTouch touch;
  touch.hertz_constant = c.hertz_constant;
  double distance;
  if (incoming ? foot_x <= 0.0 : foot_x >= 0.0) {
    distance = (z - w_foot_m - m * x) / norm;
    touch.normal_z = 1.0 / norm;
    touch.x_m = foot_x;
  } else {
    distance = std::hypot(x, z - w_foot_m);
    touch.normal_z = (z - w_foot_m) / distance;
    touch.x_m = 0.0;
  }
  touch.penetration_m = c.radius_m - distance;
  return touch;
}

inline HermiteBeamRun HermiteBeam::run() const {
  const HermiteBeamCrossing& c = c_;
  const double W = c.wheel_load_N + c.wheel_mass_kg * c.gravity;
  const double t = c.half_dip_slope, norm = std::sqrt(1.0 + t * t);
  const double dt = c.step_s, v = c.speed_m_per_s;
  // The start: static under W at the start's foot, moving with the load.
  const double x_start = c.start_x_m;
  const double foot = x_start - t * c.radius_m / norm;
  Eigen::VectorXd u = static_state(W, foot, true);
  settle_sleepers(u);
  const double dx = h_ / 16.0;
  Eigen::VectorXd ahead = static_state(W, foot + dx, true), behind = static_state(W, foot - dx, true);
  settle_sleepers(ahead);
  settle_sleepers(behind);
  Eigen::VectorXd vel = v * (ahead - behind) / (2 * dx);
  // The wheel: its centre the static approach above the deflected line.
  const double delta0 = c.hertz_constant * std::pow(W * norm, 2.0 / 3.0);  // normal force W / n_z
  const auto centre_z = [&](const Eigen::VectorXd& state, double x) {
    const double f = x - t * c.radius_m / norm;
    return -t * x + deflection_m(state, f, true) + (c.radius_m - delta0) * norm;
  };
  double z = centre_z(u, x_start);
  double zdot = (centre_z(ahead, x_start + dx) - centre_z(behind, x_start - dx)) / (2 * dx) * v;
  // Accelerations at the start: M a = f - C v - K u (the wheel's load on the beam at its foot).
  Eigen::VectorXd f0 = Eigen::VectorXd::Zero(dofs_);
  add_load(f0, foot, true, -W);
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> mass_solver(M_);
  Eigen::VectorXd acc = mass_solver.solve(f0 - C_ * vel - K_ * u);
  double zacc = 0.0;

  const Eigen::SparseMatrix<double> Keff = K_ + (2.0 / dt) * C_ + (4.0 / (dt * dt)) * M_;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(Keff);
  std::map<int, Eigen::VectorXd> column;  // K_eff^-1 e_d, as the contact reaches DOF d
  const auto column_of = [&](int d) -> const Eigen::VectorXd& {
    auto it = column.find(d);
    if (it == column.end()) {
      Eigen::VectorXd e = Eigen::VectorXd::Zero(dofs_);
      e(d) = 1.0;
      it = column.emplace(d, solver.solve(e)).first;
    }
    return it->second;
  };

  HermiteBeamRun out;
  const auto record = [&](double time, double x, double force) {
    out.time_s.push_back(time);
    out.wheel_x_m.push_back(x);
    out.force_z_N.push_back(force);
    double pad = -1e300, ballast = -1e300;
    for (std::size_t j = 0; j < sleeper_node_.size(); ++j) {
      pad = std::max(pad, pad_N(u, vel, j));
      ballast = std::max(ballast, ballast_N(u, vel, j));
    }
    out.peak_pad_N.push_back(pad);
    out.peak_ballast_N.push_back(ballast);
  };
  record(0.0, x_start, W);
  const int steps = static_cast<int>(std::ceil((c.end_x_m - c.start_x_m) / v / dt));
  const double cw = dt * dt / 4.0 / c.wheel_mass_kg;
  double q_last[2] = {W, 0.0};
  for (int n = 1; n <= steps; ++n) {
    const double time = n * dt, x = x_start + v * time;
    // Without the contact: the beam and the wheel at the step's end.
    const Eigen::VectorXd rhs = M_ * ((4.0 / (dt * dt)) * u + (4.0 / dt) * vel + acc) + C_ * ((2.0 / dt) * u + vel);
    const Eigen::VectorXd u_free = solver.solve(rhs);
    const double z_free = z + dt * zdot + dt * dt / 4.0 * (zacc - W / c.wheel_mass_kg);
    // The contact forces q_k (vertical, up on the wheel, down on the beam at
    // foot k; k = 0 the incoming rail): Newton on q = F(z(q), w(q)) with
    // z = z_free + cw sum q_k and the feet's deflections
    // w_j = w_free_j - sum_k q_k N_j^T K_eff^-1 N_k.
    int dof[2][4];
    double nn[2][4];
    double w_free[2], A[2][2];
    for (int k = 0; k < 2; ++k) {
      shape(rail_foot_x_m(c, x, k == 0), k == 0, dof[k], nn[k]);
      w_free[k] = 0.0;
      for (int a = 0; a < 4; ++a) w_free[k] += nn[k][a] * u_free(dof[k][a]);
    }
    for (int j = 0; j < 2; ++j)
      for (int k = 0; k < 2; ++k) {
        A[j][k] = 0.0;
        for (int b = 0; b < 4; ++b) {
          const Eigen::VectorXd& col = column_of(dof[k][b]);
          for (int a = 0; a < 4; ++a) A[j][k] += nn[j][a] * nn[k][b] * col(dof[j][a]);
        }
      }
    const auto residual = [&](const double qq[2], double r[2]) {
      const double zz = z_free + cw * (qq[0] + qq[1]);
      std::array<RailEndTouch, 2> touch;
      for (int j = 0; j < 2; ++j) {
        const double w = w_free[j] - A[j][0] * qq[0] - A[j][1] * qq[1];
        touch[static_cast<std::size_t>(j)] = rail_touch(c, x, zz, w, j == 0);
      }
      const std::array<double, 2> f = spanning_forces_z_N(touch, c.radius_m);
      for (int j = 0; j < 2; ++j) r[j] = qq[j] - f[static_cast<std::size_t>(j)];
    };
    double q[2] = {q_last[0], q_last[1]};  // the last step's: Newton starts near
    for (int iteration = 0; iteration < 60; ++iteration) {
      double r[2];
      residual(q, r);
      if (std::abs(r[0]) + std::abs(r[1]) < 1e-9 * W) break;
      double J[2][2];
      for (int b = 0; b < 2; ++b) {
        double qb[2] = {q[0], q[1]};
        const double dq = 1e-6 * W;
        qb[b] += dq;
        double rb[2];
        residual(qb, rb);
        for (int a = 0; a < 2; ++a) J[a][b] = (rb[a] - r[a]) / dq;
      }
      const double det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
      const double step[2] = {(J[1][1] * r[0] - J[0][1] * r[1]) / det, (-J[1][0] * r[0] + J[0][0] * r[1]) / det};
      for (int k = 0; k < 2; ++k) q[k] = std::max(0.0, q[k] - step[k]);
    }
    Eigen::VectorXd u_new = u_free;
    for (int k = 0; k < 2; ++k) {
      if (q[k] == 0.0) continue;
      for (int a = 0; a < 4; ++a) u_new -= q[k] * nn[k][a] * column_of(dof[k][a]);
    }
    const Eigen::VectorXd acc_new = (4.0 / (dt * dt)) * (u_new - u) - (4.0 / dt) * vel - acc;
    vel = vel + 0.5 * dt * (acc + acc_new);
    acc = acc_new;
    u = u_new;
    const double z_new = z_free + cw * (q[0] + q[1]);
    const double zacc_new = (q[0] + q[1] - W) / c.wheel_mass_kg;
    zdot += 0.5 * dt * (zacc + zacc_new);
    zacc = zacc_new;
    z = z_new;
    q_last[0] = q[0];
    q_last[1] = q[1];
    record(time, x, q[0] + q[1]);
  }
  return out;
}

}  // namespace railjoint::testing_reference
