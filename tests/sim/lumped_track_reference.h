#pragma once
// An independent reference for a force run on the lumped track, written in
// the tests (no Bullet, no sim/): the wheel's slice over the joint as a
// planar problem, integrated by an adaptive Dormand-Prince 5(4) scheme at a
// tolerance far below the simulation's error.
//
// The model (sim/DESIGN.md "Forces on an elastic track", issue "forces"): the
// wheel centre moves at x(t) = x0 + v t (the carrier holds the speed) and
// vertically under its weight, the static wheel load and the contact forces;
// both rail ends move together as the rail mass z_r on a pad (k_p, c_p) to
// the sleeper z_s on ballast (k_b, c_b) to the ground. Each rail end touches
// the wheel's circle (radius R) in the slice where it reaches furthest under
// the wheel (exact_jump_reference.h: the incoming end at max_y e_0(y), the
// outgoing end at min_y e_1(y) over the wheel's span), so in the x-z plane
// each rail is the region under its top line z = m x (m = -+tan(beta/2)),
// cut off at that end. The rail's nearest point to the centre is the foot of
// the perpendicular on its top line if the foot lies on the rail, else the
// cut corner; the penetration is delta = R - distance, the force
// (delta / G)^(3/2) along the normal from that point to the centre (pure
// Hertz: restitution 1), the two rail ends coupled where both bear
// (spanning_contact_reference.h). The wheel starts in its static state on
// the incoming slope.

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <vector>

#include "tests/sim/spanning_contact_reference.h"

namespace railjoint::testing_reference {

struct LumpedCrossing {
  double radius_m = 0.475;
  double wheel_mass_kg = 750.0;
  double speed_m_per_s = 30.0;
  double wheel_load_N = 112.5e3;
  double half_dip_slope = 0.0;       ///< tan(beta / 2)
  double incoming_end_x_m = 0.0;     ///< e_0: the incoming rail covers x <= e_0 (its furthest slice)
  double outgoing_start_x_m = 0.0;   ///< e_1: the outgoing rail covers x >= e_1 (its nearest slice)
  double hertz_constant = 4.2e-8;    ///< G [m/N^(2/3)]
  double rail_mass_kg = 36.12;
  double pad_stiffness = 200e6, pad_damping = 28e3;
  double sleeper_mass_kg = 140.0;
  double ballast_stiffness = 40e6, ballast_damping = 47e3;
  double gravity = 9.81;
};

/// Total vertical contact force on the wheel [N] at centre (x, z) with the rail at z_r.
inline double reference_contact_force_z_N(const LumpedCrossing& c, double x, double z, double z_r) {
  const double t = c.half_dip_slope;
  const double norm = std::sqrt(1.0 + t * t);
  // rail: top z = m x + z_r, end corner at x = e; `forward` says it covers x >= e.
  const auto one_rail = [&](double m, double e, bool forward) {
    RailEndTouch touch;
    touch.hertz_constant = c.hertz_constant;
    const double zc = z - z_r;
    const double d_line = (zc - m * x) / norm;  // distance to the top line, + above
    const double foot_x = x + m * d_line / norm; // foot of the perpendicular (normal (-m, 1)/norm)
    double distance;
    if (forward ? foot_x >= e : foot_x <= e) {
      distance = d_line;
      touch.normal_z = 1.0 / norm;
      touch.x_m = foot_x;
    } else {
      const double dx = x - e;
      const double dz = zc - m * e;
      distance = std::hypot(dx, dz);
      touch.normal_z = dz / distance;
      touch.x_m = e;
    }
    touch.penetration_m = c.radius_m - distance;
    return touch;
  };
  const std::array<double, 2> force_z =
      spanning_forces_z_N({one_rail(-t, c.incoming_end_x_m, false), one_rail(+t, c.outgoing_start_x_m, true)},
                          c.radius_m);
  return force_z[0] + force_z[1];
}

/// The state (z_w, w_w, z_r, w_r, z_s, w_s) [m, m/s] and its derivative at time t.
using LumpedState = std::array<double, 6>;

/// The vertical contact force [N] at centre (x, z) with the rail at z_r:
/// the planar model above unless a test gives its own (another rail surface).
using ContactForceZ = std::function<double(double x, double z, double z_r)>;

inline LumpedState lumped_derivative(const LumpedCrossing& c, const ContactForceZ& contact, double x,
                                     const LumpedState& y) {
  const double f = contact(x, y[0], y[2]);
  const double pad = c.pad_stiffness * (y[4] - y[2]) + c.pad_damping * (y[5] - y[3]);
  const double ballast = -c.ballast_stiffness * y[4] - c.ballast_damping * y[5];
  return {y[1], (f - c.wheel_mass_kg * c.gravity - c.wheel_load_N) / c.wheel_mass_kg,
          y[3], (-f + pad) / c.rail_mass_kg,
          y[5], (-pad + ballast) / c.sleeper_mass_kg};
}

struct ReferenceHistory {
  std::vector<double> time_s;
  std::vector<double> force_N;  ///< total vertical contact force
  std::vector<double> rail_z_m;
  std::vector<double> pad_N;  ///< the pad's spring and damper force, + in compression (no weights)
};

/// Integrates from (x0, state0) at t = 0 to end_s, reporting the force at every `report_times_s` (ascending).
inline ReferenceHistory integrate_lumped_crossing(const LumpedCrossing& c, const ContactForceZ& contact, double x0,
                                                  LumpedState y, const std::vector<double>& report_times_s,
                                                  double rtol = 1e-11) {
  // Dormand-Prince 5(4) coefficients.
  static constexpr double a21 = 1.0 / 5, a31 = 3.0 / 40, a32 = 9.0 / 40, a41 = 44.0 / 45, a42 = -56.0 / 15,
                          a43 = 32.0 / 9, a51 = 19372.0 / 6561, a52 = -25360.0 / 2187, a53 = 64448.0 / 6561,
                          a54 = -212.0 / 729, a61 = 9017.0 / 3168, a62 = -355.0 / 33, a63 = 46732.0 / 5247,
                          a64 = 49.0 / 176, a65 = -5103.0 / 18656, b1 = 35.0 / 384, b3 = 500.0 / 1113,
                          b4 = 125.0 / 192, b5 = -2187.0 / 6784, b6 = 11.0 / 84, e1 = 71.0 / 57600,
                          e3 = -71.0 / 16695, e4 = 71.0 / 1920, e5 = -17253.0 / 339200, e6 = 22.0 / 525,
                          e7 = -1.0 / 40;
  const auto f = [&](double t, const LumpedState& s) { return lumped_derivative(c, contact, x0 + c.speed_m_per_s * t, s); };
  const auto axpy = [](const LumpedState& base, std::initializer_list<std::pair<double, const LumpedState*>> terms,
                       double h) {
    LumpedState out = base;
    for (const auto& [coef, k] : terms)
      for (std::size_t i = 0; i < 6; ++i) out[i] += h * coef * (*k)[i];
    return out;
  };
  // Absolute tolerances per component: 1e-13 m, 1e-9 m/s.
  const std::array<double, 6> atol = {1e-13, 1e-9, 1e-13, 1e-9, 1e-13, 1e-9};
  ReferenceHistory out;
  double t = 0.0;
  double h = 1e-7;
  for (double target : report_times_s) {
    while (t < target) {
      const double step = std::min(h, target - t);
      const LumpedState k1 = f(t, y);
      const LumpedState k2 = f(t + step / 5, axpy(y, {{a21, &k1}}, step));
      const LumpedState k3 = f(t + 3 * step / 10, axpy(y, {{a31, &k1}, {a32, &k2}}, step));
      const LumpedState k4 = f(t + 4 * step / 5, axpy(y, {{a41, &k1}, {a42, &k2}, {a43, &k3}}, step));
      const LumpedState k5 = f(t + 8 * step / 9, axpy(y, {{a51, &k1}, {a52, &k2}, {a53, &k3}, {a54, &k4}}, step));
      const LumpedState k6 = f(t + step, axpy(y, {{a61, &k1}, {a62, &k2}, {a63, &k3}, {a64, &k4}, {a65, &k5}}, step));
      const LumpedState next = axpy(y, {{b1, &k1}, {b3, &k3}, {b4, &k4}, {b5, &k5}, {b6, &k6}}, step);
      const LumpedState k7 = f(t + step, next);
      double err = 0.0;
      for (std::size_t i = 0; i < 6; ++i) {
        const double e = step * (e1 * k1[i] + e3 * k3[i] + e4 * k4[i] + e5 * k5[i] + e6 * k6[i] + e7 * k7[i]);
        const double scale = atol[i] + rtol * std::max(std::abs(y[i]), std::abs(next[i]));
        err = std::max(err, std::abs(e) / scale);
      }
      if (err <= 1.0) {
        t += step;
        y = next;
      }
      // The contact's onset is smooth only to first order (delta^(3/2)):
      // the step never grows past 1e-6 s so no onset is stepped over.
      h = std::min(1e-6, step * std::clamp(0.9 * std::pow(std::max(err, 1e-12), -0.2), 0.2, 5.0));
    }
    out.time_s.push_back(t);
    out.force_N.push_back(contact(x0 + c.speed_m_per_s * t, y[0], y[2]));
    out.rail_z_m.push_back(y[2]);
    out.pad_N.push_back(c.pad_stiffness * (y[4] - y[2]) + c.pad_damping * (y[5] - y[3]));
  }
  return out;
}

/// The planar model's own contact (reference_contact_force_z_N).
inline ReferenceHistory integrate_lumped_crossing(const LumpedCrossing& c, double x0, LumpedState y,
                                                  const std::vector<double>& report_times_s, double rtol = 1e-11) {
  const ContactForceZ planar = [&c](double x, double z, double z_r) { return reference_contact_force_z_N(c, x, z, z_r); };
  return integrate_lumped_crossing(c, planar, x0, y, report_times_s, rtol);
}

}  // namespace railjoint::testing_reference
