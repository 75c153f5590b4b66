#include "sim/discrete_track.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include "sim/sim_settings.h"
#include "sim/timoshenko_rail.h"
#include "sim/track_support_forces.h"

namespace railjoint {

namespace {

// Beam reach beyond the wheel's run, in decay lengths 1 / beta_f. The
// static line is gone by exp(-6) at 6, but the waves an impact sends along
// the rail come back from free ends much further out: a free hinge's broad
// P1 hump at 20 m/s (6.4 ms after the impact, near the track's 75 Hz
// cut-on) moved 0.7 % between ends 6.6 and 11.4 m out, and still by up to
// 8e-4 with 12 decay lengths (249.93 against 250.13 kN on ends 16-30 m
// out), so that a start further back, which lengthens the beam, moved it
// by 0.11 % (issue 41); a 0.05 m cosine dip on continuous rail at 20 m/s
// moved 3e-4 between 6 and 12. Damping the ends instead (a dashpot to
// ground rising over their last 3 or 6 decay lengths) did not remove it.
// 16 (13.1 m on the defaults) leaves both within 1.5e-4 of ends twice as
// far; the longer beam costs next to nothing (the contact's geometry, not
// the track's nodes, dominates a step: 0.13 against 0.14 s a run).
constexpr double kEndClearance = 16.0;

// The start before the joint, in decay lengths (start_lead_m).
constexpr double kStartLeadDecayLengths = 2.0;

// Whole sleeper bays each side of the joint.
std::size_t bays_for(const DiscreteTrackSettings& settings, double half_length_m) {
  return static_cast<std::size_t>(std::max(1.0, std::ceil(half_length_m / settings.sleeper_spacing_m)));
}

// beta_f = (k_f / 4 EI)^(1/4), k_f the supports in series per metre: a
// static load's deflection decays as exp(-beta_f x) along the rail [1/m].
double decay_rate_per_m(const DiscreteTrackSettings& t) {
  return std::pow(t.support.series_stiffness_N_per_m() / t.sleeper_spacing_m / (4.0 * t.bending_stiffness_N_m2), 0.25);
}

}  // namespace

double DiscreteTrack::half_length_for_run_m(const DiscreteTrackSettings& t, double run_reach_m) {
  return run_reach_m + kEndClearance / decay_rate_per_m(t);
}

double DiscreteTrack::start_lead_m(const DiscreteTrackSettings& t) { return kStartLeadDecayLengths / decay_rate_per_m(t); }

std::size_t DiscreteTrack::node_count_for(const DiscreteTrackSettings& settings, double half_length_m) {
  return 2 * bays_for(settings, half_length_m) * static_cast<std::size_t>(settings.nodes_per_bay) + 1;
}

DiscreteTrack::DiscreteTrack(const DiscreteTrackSettings& settings, double half_length_m) : s_(settings) {
  assert(settings.nodes_per_bay >= 2 && settings.nodes_per_bay % 2 == 0);  // a sleeper at a bay's middle node
  const std::size_t per_bay = static_cast<std::size_t>(settings.nodes_per_bay);
  const double s = settings.sleeper_spacing_m;
  h_m_ = s / settings.nodes_per_bay;
  const std::size_t bays = bays_for(settings, half_length_m);
  const std::size_t nodes = node_count_for(settings, half_length_m);
  x0_m_ = -static_cast<double>(bays) * s;
  const std::size_t joint = bays * per_bay;
  const double mu = settings.mass_per_length_kg_per_m;
  mass_kg_.assign(nodes, mu * h_m_);
  mass_kg_.front() = mass_kg_.back() = 0.5 * mu * h_m_;
  spring_N_m_per_rad_.assign(nodes, settings.bending_stiffness_N_m2 / h_m_);
  spring_N_m_per_rad_.front() = spring_N_m_per_rad_.back() = 0.0;  // free ends
  if (settings.joint_bending_stiffness_N_m_per_rad) {
    // The joint node's spring stands for the joint bars in series with the
    // node's length h of rail (EI / h): 1 / k = 1 / k_joint + h / EI, so
    // stiff joint bars tend to continuous rail (0: a free hinge either way).
    const double k_joint = *settings.joint_bending_stiffness_N_m_per_rad;
    spring_N_m_per_rad_[joint] = k_joint * spring_N_m_per_rad_[joint] / (k_joint + spring_N_m_per_rad_[joint]);
    hinge_node_ = joint;
  }
  // Sleepers at +-(k + 1/2) s: the joint lies midway between two.
  for (std::size_t b = 0; b < 2 * bays; ++b) sleeper_node_.push_back(b * per_bay + per_bay / 2);
  w_m_.assign(nodes, 0.0);
  v_m_per_s_.assign(nodes, 0.0);
  load_N_.assign(nodes, 0.0);
  a_m_per_s2_.assign(nodes, 0.0);
  half_step_v_m_per_s_.assign(nodes, 0.0);
  sleeper_z_m_.assign(sleeper_node_.size(), 0.0);
  sleeper_v_m_per_s_.assign(sleeper_node_.size(), 0.0);
  sleeper_a_m_per_s2_.assign(sleeper_node_.size(), 0.0);
  sleeper_half_step_v_m_per_s_.assign(sleeper_node_.size(), 0.0);
  if (settings.timoshenko) {
    // A rotation and rotary inertia rho I h per segment (timoshenko_rail.h).
    segment_inertia_kg_m2_ = settings.timoshenko->rotary_inertia_kg_m * h_m_;
    psi_rad_.assign(nodes - 1, 0.0);
    psi_rate_rad_per_s_.assign(nodes - 1, 0.0);
    psi_acc_rad_per_s2_.assign(nodes - 1, 0.0);
    psi_half_step_rate_rad_per_s_.assign(nodes - 1, 0.0);
  }
  factorise_static_stiffness();
}

std::size_t DiscreteTrack::stencil(double x_m, double weights[4], double slopes[4]) const {
  const double position = std::clamp((x_m - x0_m_) / h_m_, 1.0, static_cast<double>(w_m_.size()) - 3.0);
  const double base = std::floor(position);
  const double t = position - base;
  const std::size_t first = static_cast<std::size_t>(base) - 1;
  // The cubic Hermite basis on the node interval [base, base + 1] (values p0,
  // p1, tangents m0, m1 per node spacing) and its derivatives in t.
  const double h00 = t * t * (2.0 * t - 3.0) + 1.0, h10 = t * (t * (t - 2.0) + 1.0);
  const double h01 = t * t * (3.0 - 2.0 * t), h11 = t * t * (t - 1.0);
  const double d00 = 6.0 * t * (t - 1.0), d10 = t * (3.0 * t - 4.0) + 1.0;
  const double d01 = -d00, d11 = t * (3.0 * t - 2.0);
  // Each node's share of p0, m0, p1, m1 over the stencil's four nodes
  // (first .. first + 3): rows are the stencil's nodes.
  double share[4][4] = {};  // [node][p0, m0, p1, m1]
  const bool left_end = hinge_node_ && first + 2 == *hinge_node_;   // [base, base + 1] ends at the hinge
  const bool right_end = hinge_node_ && first + 1 == *hinge_node_;  // it starts there
  share[1][0] = 1.0;
  share[2][2] = 1.0;
  if (left_end) {
    // The left rail's last interval: its own three nodes, the end's tangent
    // one-sided (exact for a quadratic), (3 w_j - 4 w_j-1 + w_j-2) / 2.
    share[0][1] = -0.5, share[2][1] = 0.5;
    share[0][3] = 0.5, share[1][3] = -2.0, share[2][3] = 1.5;
  } else if (right_end) {
    // The right rail's first interval, mirrored.
    share[1][1] = -1.5, share[2][1] = 2.0, share[3][1] = -0.5;
    share[1][3] = -0.5, share[3][3] = 0.5;
  } else {
    // Catmull-Rom: central tangents (w_i+1 - w_i-1) / 2.
    share[0][1] = -0.5, share[2][1] = 0.5;
    share[1][3] = -0.5, share[3][3] = 0.5;
  }
  for (int k = 0; k < 4; ++k) {
    weights[k] = share[k][0] * h00 + share[k][1] * h10 + share[k][2] * h01 + share[k][3] * h11;
    if (slopes) slopes[k] = share[k][0] * d00 + share[k][1] * d10 + share[k][2] * d01 + share[k][3] * d11;
  }
  return first;
}

double DiscreteTrack::interpolated(const std::vector<double>& nodes, double x_m) const {
  double weights[4];
  const std::size_t first = stencil(x_m, weights);
  double value = 0.0;
  for (int k = 0; k < 4; ++k) value += weights[k] * nodes[first + static_cast<std::size_t>(k)];
  return value;
}

double DiscreteTrack::deflection_m(double x_m) const { return deflection_m(x_m, std::nan("")); }

double DiscreteTrack::deflection_m(double x_m, double pressed_at_x_m) const {
  double w = interpolated(w_m_, x_m);
  for (const PointLoad& l : under_wheel_) {
    w -= local_shear_m_per_N(x_m, l.x_m == pressed_at_x_m ? x_m : l.x_m) * l.load_N;
  }
  return w;
}

DiscreteTrack::OwnShear DiscreteTrack::own_shear(double x_m, double pressed_at_x_m) const {
  for (const PointLoad& l : under_wheel_) {
    if (l.x_m != pressed_at_x_m) continue;
    const LocalShear c = local_shear_at(x_m, x_m);
    return {l.load_N, 2.0 * c.slope_per_N};  // c(x, y) is symmetric: d c(x, x) / dx = 2 dc/dx
  }
  return {};
}

double DiscreteTrack::local_shear_m_per_N(double x_m, double y_m) const { return local_shear_at(x_m, y_m).m_per_N; }

DiscreteTrack::LocalShear DiscreteTrack::local_shear_at(double x_m, double y_m) const {
  if (!s_.timoshenko) return {};
  double wx[4], sx[4], wy[4];
  const std::size_t fx = stencil(x_m, wx, sx), fy = stencil(y_m, wy);
  if (fx + 3 < fy || fy + 3 < fx) return {};  // the stencils do not meet
  double sum = 0.0, sum_slope = 0.0;  // in node spacings, and its x derivative per node spacing
  for (std::size_t i = 0; i < 4; ++i) {
    for (std::size_t j = 0; j < 4; ++j) {
      const double apart = std::abs(static_cast<double>(fx + i) - static_cast<double>(fy + j));
      sum += wx[i] * wy[j] * apart;
      sum_slope += sx[i] * wy[j] * apart;
    }
  }
  const double string_N = 2.0 * s_.timoshenko->shear_stiffness_N();
  const double cusp_slope = x_m > y_m ? -1.0 : (x_m < y_m ? 1.0 : 0.0);  // d/dx of -|x - y|
  return {(sum * h_m_ - std::abs(x_m - y_m)) / string_N, sum_slope / string_N, cusp_slope / string_N};
}

double DiscreteTrack::deflection_rate_m_per_s(double x_m) const { return interpolated(v_m_per_s_, x_m); }

double DiscreteTrack::deflection_slope(double x_m) const {
  const double position = (x_m - x0_m_) / h_m_;
  if (position < 1.0 || position > static_cast<double>(w_m_.size()) - 3.0) return 0.0;  // clamped: flat
  double weights[4], slopes[4];
  const std::size_t first = stencil(x_m, weights, slopes);
  double slope = 0.0;
  for (int k = 0; k < 4; ++k) slope += slopes[k] * w_m_[first + static_cast<std::size_t>(k)];
  return slope / h_m_;
}

double DiscreteTrack::drag_slope(double x_m, double pressed_at_x_m) const {
  double slope = deflection_slope(x_m);
  for (const PointLoad& l : under_wheel_) {
    // The contact's own force read at the contact, where the string's cusp
    // is level (its two sides' mean); another's with its cusp's side.
    const LocalShear c = l.x_m == pressed_at_x_m ? local_shear_at(x_m, x_m) : local_shear_at(x_m, l.x_m);
    slope -= (c.slope_per_N + c.cusp_slope_per_N) * l.load_N;
  }
  return slope;
}

std::size_t DiscreteTrack::sleeper_nearest(double x_m) const {
  const double bays = std::floor((x_m - x0_m_) / s_.sleeper_spacing_m);
  return static_cast<std::size_t>(std::clamp(bays, 0.0, static_cast<double>(sleeper_node_.size()) - 1.0));
}

double DiscreteTrack::nearest_sleeper_m(double x_m) const { return sleeper_z_m_[sleeper_nearest(x_m)]; }

double DiscreteTrack::sleeper_x_m(std::size_t j) const { return x0_m_ + static_cast<double>(sleeper_node_[j]) * h_m_; }

double DiscreteTrack::rail_seat_N(std::size_t j) const {
  const std::size_t n = sleeper_node_[j];
  const double weight_N = s_.mass_per_length_kg_per_m * s_.sleeper_spacing_m * kStandardGravity_m_per_s2;
  return pad_force_N(s_.support, w_m_[n], v_m_per_s_[n], sleeper_z_m_[j], sleeper_v_m_per_s_[j], weight_N);
}

double DiscreteTrack::ballast_N(std::size_t j) const {
  const double weight_N =
      (s_.mass_per_length_kg_per_m * s_.sleeper_spacing_m + s_.support.sleeper_mass_kg) * kStandardGravity_m_per_s2;
  return ballast_force_N(s_.support, sleeper_z_m_[j], sleeper_v_m_per_s_[j], weight_N);
}

void DiscreteTrack::record_supports_near(double x_m, std::size_t count) {
  std::vector<std::size_t> order(sleeper_node_.size());
  for (std::size_t j = 0; j < order.size(); ++j) order[j] = j;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return std::abs(sleeper_x_m(a) - x_m) < std::abs(sleeper_x_m(b) - x_m);
  });
  order.resize(std::min(count, order.size()));
  std::sort(order.begin(), order.end());
  recorded_sleepers_ = order;
  support_histories_.assign(order.size(), SupportHistory{});
  for (std::size_t k = 0; k < order.size(); ++k) support_histories_[k].x_m = sleeper_x_m(order[k]);
}

void DiscreteTrack::note_static_support_forces() {
  for (std::size_t k = 0; k < recorded_sleepers_.size() && k < support_histories_.size(); ++k) {
    support_histories_[k].rail_seat_static_N = rail_seat_N(recorded_sleepers_[k]);
    support_histories_[k].ballast_static_N = ballast_N(recorded_sleepers_[k]);
  }
}

std::vector<SupportHistory> DiscreteTrack::take_support_histories() { return std::move(support_histories_); }

void DiscreteTrack::press(double x_m, double force_N) {
  double weights[4];
  const std::size_t first = stencil(x_m, weights);
  for (int k = 0; k < 4; ++k) load_N_[first + static_cast<std::size_t>(k)] += weights[k] * force_N;
  if (s_.timoshenko) pressed_.push_back({force_N, x_m});
}

double DiscreteTrack::kick_mobility_per_kg(double x_m, double y_m) const {
  double wx[4], wy[4];
  const std::size_t fx = stencil(x_m, wx), fy = stencil(y_m, wy);
  double mobility = 0.0;
  for (std::size_t i = 0; i < 4; ++i) {
    const std::size_t node = fx + i;
    if (node < fy || node > fy + 3) continue;
    mobility += wx[i] * wy[node - fy] / mass_kg_[node];
  }
  return mobility;
}

// f = -dU/dw of the rotational springs: node i's spring k turns by
// theta = (w[i+1] - 2 w[i] + w[i-1]) / h and stores k theta^2 / 2.
void DiscreteTrack::bending_forces(const std::vector<double>& w, std::vector<double>& f) const {
  std::fill(f.begin(), f.end(), 0.0);
  for (std::size_t i = 1; i + 1 < w.size(); ++i) {
    const double moment_over_h = spring_N_m_per_rad_[i] * (w[i + 1] - 2.0 * w[i] + w[i - 1]) / (h_m_ * h_m_);
    f[i - 1] -= moment_over_h;
    f[i] += 2.0 * moment_over_h;
    f[i + 1] -= moment_over_h;
  }
}

timoshenko_rail::Springs DiscreteTrack::timoshenko_springs() const {
  return {spring_N_m_per_rad_, s_.timoshenko->shear_stiffness_N(), h_m_};
}

void DiscreteTrack::advance(double dt_s) {
  const double half = 0.5 * dt_s;
  for (std::size_t k = 0; k < psi_rad_.size(); ++k) {
    psi_half_step_rate_rad_per_s_[k] = psi_rate_rad_per_s_[k] + half * psi_acc_rad_per_s2_[k];
    psi_rad_[k] += psi_half_step_rate_rad_per_s_[k] * dt_s;
    psi_rate_rad_per_s_[k] = psi_half_step_rate_rad_per_s_[k] + half * psi_acc_rad_per_s2_[k];
  }
  for (std::size_t i = 0; i < w_m_.size(); ++i) {
    half_step_v_m_per_s_[i] = v_m_per_s_[i] + half * a_m_per_s2_[i];
    w_m_[i] += half_step_v_m_per_s_[i] * dt_s;
    v_m_per_s_[i] = half_step_v_m_per_s_[i] + half * a_m_per_s2_[i];
  }
  for (std::size_t j = 0; j < sleeper_node_.size(); ++j) {
    sleeper_half_step_v_m_per_s_[j] = sleeper_v_m_per_s_[j] + half * sleeper_a_m_per_s2_[j];
    sleeper_z_m_[j] += sleeper_half_step_v_m_per_s_[j] * dt_s;
    sleeper_v_m_per_s_[j] = sleeper_half_step_v_m_per_s_[j] + half * sleeper_a_m_per_s2_[j];
  }
}

void DiscreteTrack::accelerate(double half_step_s) {
  // The next step's read-out takes this step's forces (deflection_m): one
  // step late. P1 moves by 2.5e-5 against a step 16 times finer with or
  // without the local part (a reviewer's runs): the chain's own stepping,
  // not the lag.
  under_wheel_.swap(pressed_);
  pressed_.clear();
  std::vector<double>& f = a_m_per_s2_;  // the forces first, then divided by the masses
  if (s_.timoshenko) {
    std::vector<double>& torque = psi_acc_rad_per_s2_;  // the torques first, then divided by the inertias
    std::fill(f.begin(), f.end(), 0.0);
    std::fill(torque.begin(), torque.end(), 0.0);
    timoshenko_rail::add_forces(timoshenko_springs(), w_m_, psi_rad_, f, torque);
    for (std::size_t k = 0; k < psi_rad_.size(); ++k) {
      torque[k] /= segment_inertia_kg_m2_;
      psi_rate_rad_per_s_[k] = psi_half_step_rate_rad_per_s_[k] + half_step_s * torque[k];
    }
  } else {
    bending_forces(w_m_, f);
  }
  const double kp = s_.support.pad_stiffness_N_per_m, cp = s_.support.pad_damping_N_s_per_m;
  const double kb = s_.support.ballast_stiffness_N_per_m, cb = s_.support.ballast_damping_N_s_per_m;
  for (std::size_t j = 0; j < sleeper_node_.size(); ++j) {
    const std::size_t n = sleeper_node_[j];
    const double pad_N = kp * (sleeper_z_m_[j] - w_m_[n]) + cp * (sleeper_v_m_per_s_[j] - v_m_per_s_[n]);
    const double ballast_N = -kb * sleeper_z_m_[j] - cb * sleeper_v_m_per_s_[j];
    f[n] += pad_N;
    sleeper_a_m_per_s2_[j] = (ballast_N - pad_N) / s_.support.sleeper_mass_kg;
    sleeper_v_m_per_s_[j] = sleeper_half_step_v_m_per_s_[j] + half_step_s * sleeper_a_m_per_s2_[j];
  }
  for (std::size_t i = 0; i < w_m_.size(); ++i) {
    a_m_per_s2_[i] = (f[i] - load_N_[i]) / mass_kg_[i];
    v_m_per_s_[i] = half_step_v_m_per_s_[i] + half_step_s * a_m_per_s2_[i];
    load_N_[i] = 0.0;
  }
}

void DiscreteTrack::record_supports() {
  // The supports' forces at the step's end, with its rates.
  for (std::size_t k = 0; k < recorded_sleepers_.size() && k < support_histories_.size(); ++k) {
    support_histories_[k].rail_seat_N.push_back(rail_seat_N(recorded_sleepers_[k]));
    support_histories_[k].ballast_N.push_back(ballast_N(recorded_sleepers_[k]));
  }
}

// The static stiffness matrix: the rotational springs' (k theta^2 / 2 with
// theta = (w[i+1] - 2 w[i] + w[i-1]) / h, as bending_forces) and pad and
// ballast in series under each sleeper (at rest the sleeper takes the pad's
// force on to the ballast). Factorised once: it does not depend on the load.
void DiscreteTrack::factorise_static_stiffness() {
  const Eigen::Index n = static_cast<Eigen::Index>(w_m_.size());
  std::vector<Eigen::Triplet<double>> entries;  // summed where they repeat
  entries.reserve(9 * static_cast<std::size_t>(n) + sleeper_node_.size());
  if (s_.timoshenko) {
    // w and psi interleaved (timoshenko_rail.h): banded as the Euler chain's.
    timoshenko_rail::add_stiffness(timoshenko_springs(), entries);
    const double series = s_.support.series_stiffness_N_per_m();
    for (std::size_t node : sleeper_node_) entries.emplace_back(w_dof(node), w_dof(node), series);
    Eigen::SparseMatrix<double> K(2 * n - 1, 2 * n - 1);
    K.setFromTriplets(entries.begin(), entries.end());
    static_stiffness_.compute(K);
    return;
  }
  for (Eigen::Index i = 1; i + 1 < n; ++i) {
    const double k = spring_N_m_per_rad_[static_cast<std::size_t>(i)] / (h_m_ * h_m_);
    const double g[3] = {1.0, -2.0, 1.0};
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) entries.emplace_back(i - 1 + a, i - 1 + b, k * g[a] * g[b]);
  }
  const double series = s_.support.series_stiffness_N_per_m();
  for (std::size_t node : sleeper_node_) {
    entries.emplace_back(static_cast<Eigen::Index>(node), static_cast<Eigen::Index>(node), series);
  }
  Eigen::SparseMatrix<double> K(n, n);
  K.setFromTriplets(entries.begin(), entries.end());
  static_stiffness_.compute(K);
}

Eigen::Index DiscreteTrack::w_dof(std::size_t node) const {
  return static_cast<Eigen::Index>(s_.timoshenko ? 2 * node : node);
}

std::vector<double> DiscreteTrack::static_solution(double load_N, double x_m) const {
  const Eigen::Index n = static_stiffness_.rows();
  Eigen::VectorXd f = Eigen::VectorXd::Zero(n);
  double weights[4];
  const std::size_t first = stencil(x_m, weights);
  for (std::size_t k = 0; k < 4; ++k) f(w_dof(first + k)) = -weights[k] * load_N;
  const Eigen::VectorXd u = static_stiffness_.solve(f);
  return std::vector<double>(u.data(), u.data() + n);
}

void DiscreteTrack::set_rail(const std::vector<double>& u, std::vector<double>& w, std::vector<double>& psi) const {
  if (!s_.timoshenko) {
    w = u;
    return;
  }
  for (std::size_t i = 0; i < w.size(); ++i) w[i] = u[2 * i];
  for (std::size_t k = 0; k < psi.size(); ++k) psi[k] = u[2 * k + 1];
}

void DiscreteTrack::rest_under(double load_N, double x_m, double load_speed_m_per_s) {
  rest_under(std::vector<PointLoad>{{load_N, x_m}}, load_speed_m_per_s);
}

void DiscreteTrack::rest_under(const std::vector<PointLoad>& loads, double load_speed_m_per_s) {
  // (shift of every load) => (the static deflection under them all).
  const auto static_under = [&](double shift_m) {
    std::vector<double> w = static_solution(loads.front().load_N, loads.front().x_m + shift_m);
    for (std::size_t k = 1; k < loads.size(); ++k) {
      const std::vector<double> more = static_solution(loads[k].load_N, loads[k].x_m + shift_m);
      for (std::size_t i = 0; i < w.size(); ++i) w[i] += more[i];
    }
    return w;
  };
  set_rail(static_under(0.0), w_m_, psi_rad_);
  if (s_.timoshenko) under_wheel_ = loads;
  pressed_.clear();
  std::fill(v_m_per_s_.begin(), v_m_per_s_.end(), 0.0);
  std::fill(psi_rate_rad_per_s_.begin(), psi_rate_rad_per_s_.end(), 0.0);
  if (load_speed_m_per_s != 0.0) {
    // The static state is smooth in the load's position (the interpolation
    // is C1): a central difference over an eighth of a node spacing.
    const double dx = h_m_ / 8.0;
    const std::vector<double> ahead = static_under(dx);
    const std::vector<double> behind = static_under(-dx);
    std::vector<double> rate(ahead.size());
    for (std::size_t i = 0; i < rate.size(); ++i) {
      rate[i] = load_speed_m_per_s * (ahead[i] - behind[i]) / (2.0 * dx);
    }
    set_rail(rate, v_m_per_s_, psi_rate_rad_per_s_);
  }
  const double share = s_.support.pad_stiffness_N_per_m / (s_.support.pad_stiffness_N_per_m + s_.support.ballast_stiffness_N_per_m);
  for (std::size_t j = 0; j < sleeper_node_.size(); ++j) {
    sleeper_z_m_[j] = share * w_m_[sleeper_node_[j]];
    sleeper_v_m_per_s_[j] = share * v_m_per_s_[sleeper_node_[j]];
  }
  start_stepping_here();
}

void DiscreteTrack::start_stepping_here() {
  // The accelerations are the next accelerate()'s, the half-step rates the
  // state's own.
  std::fill(a_m_per_s2_.begin(), a_m_per_s2_.end(), 0.0);
  std::fill(sleeper_a_m_per_s2_.begin(), sleeper_a_m_per_s2_.end(), 0.0);
  std::fill(psi_acc_rad_per_s2_.begin(), psi_acc_rad_per_s2_.end(), 0.0);
  half_step_v_m_per_s_ = v_m_per_s_;
  sleeper_half_step_v_m_per_s_ = sleeper_v_m_per_s_;
  psi_half_step_rate_rad_per_s_ = psi_rate_rad_per_s_;
}

std::vector<DiscreteTrack::LineUnderLoad> DiscreteTrack::static_line_under(const std::vector<PointLoad>& loads) {
  // (shift of every load) => (the static deflection under each). The line
  // is C1 in the loads' place, as the interpolation: a central difference
  // over 0.1 mm, the unshifted state last, which the track keeps.
  const auto under_each = [&](double shift_m) {
    std::vector<PointLoad> moved = loads;
    for (PointLoad& l : moved) l.x_m += shift_m;
    rest_under(moved);
    std::vector<double> z_m;
    for (const PointLoad& l : moved) z_m.push_back(deflection_m(l.x_m));
    return z_m;
  };
  constexpr double dx = 1e-4;
  const std::vector<double> ahead = under_each(dx);
  const std::vector<double> behind = under_each(-dx);
  const std::vector<double> here = under_each(0.0);
  std::vector<LineUnderLoad> out;
  for (std::size_t k = 0; k < loads.size(); ++k) out.push_back({here[k], (ahead[k] - behind[k]) / (2.0 * dx)});
  return out;
}

void DiscreteTrack::add_motion(const Motion& delta, double delta_x0_m, double shift_m) {
  // Node i at x0 + i h reads delta's node j at x0 + i h + shift: j = i + offset.
  const double offset = std::round((x0_m_ + shift_m - delta_x0_m) / h_m_);
  for (std::size_t i = 0; i < w_m_.size(); ++i) {
    const double j = static_cast<double>(i) + offset;
    if (j < 0.0 || j >= static_cast<double>(delta.w_m.size())) continue;
    w_m_[i] += delta.w_m[static_cast<std::size_t>(j)];
    v_m_per_s_[i] += delta.v_m_per_s[static_cast<std::size_t>(j)];
  }
  // Segments shift with their nodes.
  for (std::size_t k = 0; k < psi_rad_.size(); ++k) {
    const double j = static_cast<double>(k) + offset;
    if (j < 0.0 || j >= static_cast<double>(delta.psi_rad.size())) continue;
    psi_rad_[k] += delta.psi_rad[static_cast<std::size_t>(j)];
    psi_rate_rad_per_s_[k] += delta.psi_rate_rad_per_s[static_cast<std::size_t>(j)];
  }
  // Sleepers lie at node n b + n / 2 on both tracks (n nodes a bay): sleeper b reads b + offset / n.
  const double sleeper_offset = offset / s_.nodes_per_bay;
  for (std::size_t b = 0; b < sleeper_z_m_.size(); ++b) {
    const double c = static_cast<double>(b) + sleeper_offset;
    if (c < 0.0 || c >= static_cast<double>(delta.sleeper_z_m.size())) continue;
    sleeper_z_m_[b] += delta.sleeper_z_m[static_cast<std::size_t>(c)];
    sleeper_v_m_per_s_[b] += delta.sleeper_v_m_per_s[static_cast<std::size_t>(c)];
  }
  start_stepping_here();
}

void DiscreteTrack::shift_motion(double shift_m) {
  const Motion now = motion();
  std::fill(w_m_.begin(), w_m_.end(), 0.0);
  std::fill(v_m_per_s_.begin(), v_m_per_s_.end(), 0.0);
  std::fill(sleeper_z_m_.begin(), sleeper_z_m_.end(), 0.0);
  std::fill(sleeper_v_m_per_s_.begin(), sleeper_v_m_per_s_.end(), 0.0);
  std::fill(psi_rad_.begin(), psi_rad_.end(), 0.0);
  std::fill(psi_rate_rad_per_s_.begin(), psi_rate_rad_per_s_.end(), 0.0);
  add_motion(now, x0_m_, shift_m);
  for (PointLoad& l : under_wheel_) l.x_m -= shift_m;
}

double DiscreteTrack::energy_J() const {
  double e = 0.0;
  if (s_.timoshenko) {
    e += timoshenko_rail::strain_energy_J(timoshenko_springs(), w_m_, psi_rad_);
    for (double rate : psi_rate_rad_per_s_) e += 0.5 * segment_inertia_kg_m2_ * rate * rate;
    // The local shear under the wheel (deflection_m): a spring in series
    // with the contact, F c F / 2.
    for (const PointLoad& a : under_wheel_)
      for (const PointLoad& b : under_wheel_) e += 0.5 * a.load_N * local_shear_m_per_N(a.x_m, b.x_m) * b.load_N;
  }
  for (std::size_t i = 0; i < w_m_.size(); ++i) {
    e += 0.5 * mass_kg_[i] * v_m_per_s_[i] * v_m_per_s_[i];
    if (!s_.timoshenko && i > 0 && i + 1 < w_m_.size()) {
      const double theta = (w_m_[i + 1] - 2.0 * w_m_[i] + w_m_[i - 1]) / h_m_;
      e += 0.5 * spring_N_m_per_rad_[i] * theta * theta;
    }
  }
  for (std::size_t j = 0; j < sleeper_node_.size(); ++j) {
    const double pad_m = sleeper_z_m_[j] - w_m_[sleeper_node_[j]];
    e += 0.5 * s_.support.sleeper_mass_kg * sleeper_v_m_per_s_[j] * sleeper_v_m_per_s_[j] +
         0.5 * s_.support.pad_stiffness_N_per_m * pad_m * pad_m + 0.5 * s_.support.ballast_stiffness_N_per_m * sleeper_z_m_[j] * sleeper_z_m_[j];
  }
  return e;
}

double DiscreteTrack::dissipation_W() const {
  double p = 0.0;
  for (std::size_t j = 0; j < sleeper_node_.size(); ++j) {
    const double pad_rate = sleeper_v_m_per_s_[j] - v_m_per_s_[sleeper_node_[j]];
    p += s_.support.pad_damping_N_s_per_m * pad_rate * pad_rate +
         s_.support.ballast_damping_N_s_per_m * sleeper_v_m_per_s_[j] * sleeper_v_m_per_s_[j];
  }
  return p;
}

double DiscreteTrack::highest_frequency_rad_per_s(const DiscreteTrackSettings& settings) {
  const double h_m = settings.sleeper_spacing_m / settings.nodes_per_bay;
  if (const std::optional<TimoshenkoRailSettings>& t = settings.timoshenko) {
    return timoshenko_rail::highest_frequency_bound_rad_per_s(settings.bending_stiffness_N_m2,
                                                              settings.mass_per_length_kg_per_m,
                                                              t->shear_stiffness_N(), t->rotary_inertia_kg_m, h_m);
  }
  return 4.0 / (h_m * h_m) * std::sqrt(settings.bending_stiffness_N_m2 / settings.mass_per_length_kg_per_m);
}

double DiscreteTrack::static_stiffness_N_per_m(double x_m) const {
  std::vector<double> w(w_m_.size()), psi(psi_rad_.size());
  set_rail(static_solution(1.0, x_m), w, psi);
  return -1.0 / (interpolated(w, x_m) - local_shear_m_per_N(x_m, x_m));
}

JenkinsTrack DiscreteTrack::jenkins_equivalent() const {
  JenkinsTrack j;
  j.track_stiffness_N_per_m = static_stiffness_N_per_m(0.0);
  const double sleepers = j.track_stiffness_N_per_m / s_.support.series_stiffness_N_per_m();
  const double bay_of_rail_kg = s_.mass_per_length_kg_per_m * s_.sleeper_spacing_m;
  j.track_mass_p1_kg = bay_of_rail_kg;
  j.track_mass_p2_kg = sleepers * (bay_of_rail_kg + s_.support.sleeper_mass_kg);
  j.track_damping_N_s_per_m = sleepers * s_.support.ballast_damping_N_s_per_m;
  return j;
}

}  // namespace railjoint
