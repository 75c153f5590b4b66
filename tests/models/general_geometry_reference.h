#pragma once
// An independent reference for the general kinematic model
// (models/wheel_rail_envelope.h), written from the geometry alone and
// sharing no code with models/: long double throughout, every maximum found
// by golden-section search on values (no derivatives, no closed forms), the
// crossing by bisection, and the slopes of the centre path by one-sided
// finite differences of its heights.
//
// The centre height with the centre at x is the highest, over rail points
// (x', y) the wheel spans, of top(x', y) + sqrt(r(y)^2 - (x - x')^2): a rail
// point is inside the wheel exactly when it is inside its slice's circle.
//
// Accuracy (why the tests' tolerances are what they are): golden-section
// finds a maximum's value to the round-off of long double (~1e-19 m here)
// even though its position is only good to sqrt(eps); the one-sided
// three-point slope with h = 2e-6 m then carries a truncation error of about
// h^2 |z'''| / 3 < 1e-12 (|z'''| ~ 1/R^2 on a circle) and a round-off of about
// 1e-19 / h = 5e-14, so the reference jump is good to ~1e-11 of itself.

#include <cmath>
#include <numbers>

namespace railjoint::reference {

using Real = long double;

struct Geometry {
  // Joint
  bool step = false;        // a step joint (square, level rails, outgoing at u0)
  Real theta_rad = 0.5L;    // junction angle (inclined)
  Real beta_rad = 0.03L;    // dip angle (inclined)
  Real u0_m = 0.0L;         // step height (step)
  Real half_width_m = 0.02L;
  Real half_length_m = 0.5L;
  Real gap_m = 0.0L;        // normal to the cut (inclined), along x (step)
  Real crown_radius_m = 0.0L;  // 0: flat
  bool head_60e1 = false;      // the 60E1 head instead (crown_radius ignored)
  int dip_shape = 0;        // 0 linear, 1 quadratic, 2 cosine
  Real dip_length_m = 0.3L;
  // Wheel
  Real radius_m = 0.475L;
  Real width_m = 0.0L;
  Real lateral_m = 0.0L;
  Real conicity = 0.0L;
};

// The droop of one rail end at distance s from the V (s < 0: past the V).
inline Real droop_m(const Geometry& g, Real s) {
  const Real t = std::tan(g.beta_rad / 2);
  if (g.dip_shape == 0 || s <= 0) return t * s;
  const Real D = g.dip_length_m;
  const Real u = s < D ? s : D;
  if (g.dip_shape == 1) return t * u - t * u * u / (2 * D);
  return 2 * t * D / std::numbers::pi_v<Real> * std::sin(std::numbers::pi_v<Real> * u / (2 * D));
}

// 60E1 (EN 13674-1): arcs of 300, 80 and 13 mm meeting tangentially, the
// first two ending at the drawing's half-chords 10.228 and 26.0265 mm. Walked
// here by the angle phi of the outward normal from the vertical: an arc of
// radius r whose normal at its start (y0, z0) has angle phi0 has its centre
// r along -(sin phi0, cos phi0); at y the normal's sine is (y - c_y) / r.
inline Real head_60e1_m(Real y) {
  const Real radius[3] = {0.300L, 0.080L, 0.013L};
  const Real end_y[2] = {0.010228L, 0.0260265L};
  const Real a = std::abs(y);
  Real y0 = 0, z0 = 0, phi0 = 0;  // the crest
  for (int i = 0; i < 3; ++i) {
    const Real cy = y0 - radius[i] * std::sin(phi0), cz = z0 - radius[i] * std::cos(phi0);
    const Real s = (a - cy) / radius[i];
    if (i == 2 || a <= end_y[i]) return cz + radius[i] * std::sqrt(1 - s * s);
    phi0 = std::asin((end_y[i] - cy) / radius[i]);
    y0 = end_y[i];
    z0 = cz + radius[i] * std::cos(phi0);
  }
  return 0;
}

inline Real crown_m(const Geometry& g, Real y) {
  if (g.head_60e1) return head_60e1_m(y);
  return g.crown_radius_m == 0 ? Real(0) : std::sqrt(g.crown_radius_m * g.crown_radius_m - y * y) - g.crown_radius_m;
}

// Rail `rail` (0 incoming, 1 outgoing) at (x, y): top height, and the x range it covers at y.
inline Real top_m(const Geometry& g, int rail, Real x, Real y) {
  const Real along = g.step ? (rail == 0 ? Real(0) : g.u0_m) : droop_m(g, rail == 0 ? -x : x);
  return crown_m(g, y) + along;
}
inline Real cut_m(const Geometry& g, int rail, Real y) {
  const Real side = rail == 0 ? -1 : 1;
  if (g.step) return side * g.gap_m / 2;
  const Real square = std::abs(g.theta_rad - std::numbers::pi_v<Real> / 2) < 1e-12L;
  const Real x_cut = square ? Real(0) : y * std::cos(g.theta_rad) / std::sin(g.theta_rad);
  return x_cut + side * g.gap_m / (2 * std::sin(g.theta_rad));
}

// Golden-section maximum of a unimodal f on [a, b]: its value.
template <typename F>
Real golden_max(F f, Real a, Real b) {
  const Real k = (std::sqrt(Real(5)) - 1) / 2;
  Real c = b - k * (b - a), d = a + k * (b - a);
  Real fc = f(c), fd = f(d);
  for (int i = 0; i < 64 && b - a > 0; ++i) {
    if (fc < fd) {
      a = c; c = d; fc = fd; d = a + k * (b - a); fd = f(d);
    } else {
      b = d; d = c; fd = fc; c = b - k * (b - a); fc = f(c);
    }
  }
  Real best = fc > fd ? fc : fd;
  const Real fa = f(a), fb = f(b);
  if (fa > best) best = fa;
  if (fb > best) best = fb;
  return best;
}

inline Real slice_radius_m(const Geometry& g, Real y) { return g.radius_m - g.conicity * (y - g.lateral_m); }

// One rail's support of the wheel with its centre at x (-inf out of reach).
inline Real rail_height_m(const Geometry& g, int rail, Real x) {
  const Real lo_y = std::max(g.lateral_m - g.width_m / 2, -g.half_width_m);
  const Real hi_y = std::min(g.lateral_m + g.width_m / 2, g.half_width_m);
  const auto slice = [&](Real y) -> Real {
    const Real r = slice_radius_m(g, y);
    const Real a = std::max(rail == 0 ? -g.half_length_m : cut_m(g, 1, y), x - r);
    const Real b = std::min(rail == 0 ? cut_m(g, 0, y) : g.half_length_m, x + r);
    if (!(a <= b)) return -1;  // out of reach: a metre below any support
    return golden_max([&](Real xp) { return top_m(g, rail, xp, y) + std::sqrt(std::max(Real(0), r * r - (x - xp) * (x - xp))); },
                      a, b);
  };
  return lo_y == hi_y ? slice(lo_y) : golden_max(slice, lo_y, hi_y);
}

struct Jump {
  Real centre_x_m = 0;
  Real slope_before = 0;
  Real slope_after = 0;
  Real jump_per_Mv() const { return slope_after - slope_before; }
};

// The crossing (bisection of outgoing - incoming) and the one-sided slopes
// of the path there: the incoming rail's from behind, the outgoing one's ahead.
inline Jump crossing(const Geometry& g) {
  const auto diff = [&](Real x) { return rail_height_m(g, 1, x) - rail_height_m(g, 0, x); };
  Real lo = -0.9L * g.radius_m, hi = 0.9L * g.radius_m;
  for (int i = 0; i < 70; ++i) {
    const Real mid = (lo + hi) / 2;
    (diff(mid) < 0 ? lo : hi) = mid;
  }
  Jump j;
  j.centre_x_m = (lo + hi) / 2;
  const Real h = 2e-6L, x = j.centre_x_m;
  const auto one_sided = [&](int rail, Real step) {
    return (3 * rail_height_m(g, rail, x) - 4 * rail_height_m(g, rail, x - step) + rail_height_m(g, rail, x - 2 * step)) /
           (2 * step);
  };
  j.slope_before = one_sided(0, h);
  j.slope_after = one_sided(1, -h);
  return j;
}

}  // namespace railjoint::reference
