#pragma once
// The planar slice model of lumped_track_reference.h generalised to the real
// surfaces (a crowned or 60E1 head, a conical tread, a curved dip), written
// in the tests with no sim/ code: the wheel still moves in x and z only and
// both rail ends move with the rail mass z_r, so each rail end's support of
// the wheel depends on x alone. Per rail end r and centre x:
//  - h_r(x): the centre height at which the wheel touches it, the highest
//    top(x', y) + sqrt(r(y)^2 - (x - x')^2) over the rail's points under the
//    wheel's span (general_geometry_reference.h's definition, maximised here
//    by golden section returning the touching point (x_p, y_p));
//  - the normal there: in the slice's plane from the touching point to the
//    axle, (x - x_p, h_r - top) / r, tilted across by the head's slope c'(y_p)
//    (a face's normal is (-top_x, -top_y, 1) normalised, which the slice's
//    tangency makes equal to this); its vertical part N_z;
//  - the approach along it, delta = (h_r(x) + z_r - z) N_z (first order in
//    delta / R, ~1e-4), and Hertz's force (delta / G)^(3/2), vertical part
//    times N_z, the two rail ends coupled where both bear
//    (spanning_contact_reference.h, at the touching points' x_p);
//  - G: where the touching point is inside the rail's top and inside the
//    tread, Hertz's elliptical constant from the relative curvatures there
//    (Johnson 1985, 4.2, through models/hertz_ellipse's elliptical_hertz: a
//    model input, validated on its own in tests/models); the curvatures are
//    written here (A and B half their sums): the rolling circle 1 / (r sqrt(1 + r'^2)) (Meusnier), the
//    cone's 0 across, the head's -c'' / (1 + c'^2)^(3/2) across and the
//    dip's -top_xx / (1 + top_x^2)^(3/2) along, by central differences. On
//    the rail end's cut edge, the tread's rim or a thin disc (an edge) and
//    on a line (no curvature across) the thesis's empirical 3.86e-8 R^-0.115.
// h_r, N_z and G are tabulated every 0.1 mm along the run and interpolated
// linearly (h'' ~ 1 / R: 2.6e-9 m off at mid cell, 8e-5 of a 50 um approach,
// 1e-4 of the force); G where both nodes of the cell agree, else (the
// contact moves between a face and an edge, where G steps by up to 14 %)
// from the touching point at x itself.

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

#include "models/hertz_contact.h"
#include "models/hertz_ellipse.h"
#include "tests/models/general_geometry_reference.h"
#include "tests/sim/spanning_contact_reference.h"

namespace railjoint::testing_reference {

class RealSurfaceRails {
 public:
  RealSurfaceRails(const reference::Geometry& g, double x_from_m, double x_to_m) : g_(g), x0_(x_from_m) {
    const int n = static_cast<int>(std::ceil((x_to_m - x_from_m) / kCell_m)) + 2;
    for (int rail = 0; rail < 2; ++rail) {
      for (int i = 0; i < n; ++i) nodes_[rail].push_back(node(rail, x_from_m + kCell_m * i));
    }
  }

  /// The total vertical contact force on the wheel at centre (x, z), rails at z_r [N].
  double force_z_N(double x, double z, double z_r) const {
    const double u = (x - x0_) / kCell_m;
    const auto i = static_cast<std::size_t>(std::clamp(std::floor(u), 0.0, static_cast<double>(nodes_[0].size() - 2)));
    const double w = u - static_cast<double>(i);
    std::array<RailEndTouch, 2> touch;
    for (int rail = 0; rail < 2; ++rail) {
      const Node& a = nodes_[rail][i];
      const Node& b = nodes_[rail][i + 1];
      if (!a.reach || !b.reach) continue;
      const double h = a.height_m + w * (b.height_m - a.height_m);
      const double n_z = a.normal_z + w * (b.normal_z - a.normal_z);
      // G steps where the contact moves between a face and an edge: there
      // the touching point at x itself decides.
      // (Elsewhere it drifts smoothly as the contact moves across the head:
      // a cell changes it by ~1e-5.)
      const bool steps = std::abs(b.hertz_constant - a.hertz_constant) > 1e-3 * a.hertz_constant;
      RailEndTouch& t = touch[static_cast<std::size_t>(rail)];
      const Node here = steps ? node(rail, x) : a;
      t.hertz_constant = steps ? here.hertz_constant : a.hertz_constant + w * (b.hertz_constant - a.hertz_constant);
      t.ellipse = here.ellipse;
      t.x_m = a.touch_x_m + w * (b.touch_x_m - a.touch_x_m);
      t.normal_z = n_z;
      t.penetration_m = (h + z_r - z) * n_z;
    }
    const std::array<double, 2> force_z = spanning_forces_z_N(
        touch, static_cast<double>(g_.radius_m), reference_coupling_modulus_Pa(g_.gap_m > 0));
    return force_z[0] + force_z[1];
  }

  /// Rail `rail`'s support height, normal's z and Hertz's constant at the node nearest x.
  double height_m(int rail, double x) const { return nearest(rail, x).height_m; }
  double normal_z(int rail, double x) const { return nearest(rail, x).normal_z; }
  double hertz_constant(int rail, double x) const { return nearest(rail, x).hertz_constant; }

 private:
  static constexpr double kCell_m = 1e-4;
  struct Node {
    bool reach = false;
    double height_m = 0.0;
    double normal_z = 1.0;
    double hertz_constant = 0.0;
    double touch_x_m = 0.0;                  ///< the touching point along the track
    std::optional<EllipticalHertz> ellipse;  ///< where the contact is one
  };
  struct Touch {
    double value = -1.0;
    double at = 0.0;
  };

  // Golden-section maximum of a unimodal f on [a, b] and where it is, to
  // 1e-10 m in its place: the value, flat at the maximum, is then good to
  // ~(1e-10)^2 / R = 2e-20 m.
  template <typename F>
  static Touch golden(F f, double a, double b) {
    const double k = (std::sqrt(5.0) - 1.0) / 2.0;
    double c = b - k * (b - a), d = a + k * (b - a);
    double fc = f(c), fd = f(d);
    for (int i = 0; i < 80 && b - a > 1e-10; ++i) {
      if (fc < fd) {
        a = c; c = d; fc = fd; d = a + k * (b - a); fd = f(d);
      } else {
        b = d; d = c; fd = fc; c = b - k * (b - a); fc = f(c);
      }
    }
    Touch best = fc > fd ? Touch{fc, c} : Touch{fd, d};
    const double fa = f(a), fb = f(b);
    if (fa > best.value) best = {fa, a};
    if (fb > best.value) best = {fb, b};
    return best;
  }

  double top(int rail, double x, double y) const {
    return static_cast<double>(reference::top_m(g_, rail, x, y));
  }
  double radius(double y) const { return static_cast<double>(reference::slice_radius_m(g_, y)); }
  double crown(double y) const { return static_cast<double>(reference::crown_m(g_, y)); }

  // The slice at y: its rail extent and the touching point's x.
  Touch slice(int rail, double x, double y) const {
    const double r = radius(y);
    const double half = static_cast<double>(g_.half_length_m);
    // The touching point leans from below the axle by the top's slope, at
    // most 0.05 here: within r / 10 of it.
    const double a = std::max(rail == 0 ? -half : static_cast<double>(reference::cut_m(g_, 1, y)), x - 0.1 * r);
    const double b = std::min(rail == 0 ? static_cast<double>(reference::cut_m(g_, 0, y)) : half, x + 0.1 * r);
    if (!(a <= b)) return {};
    return golden([&](double xp) { return top(rail, xp, y) + std::sqrt(std::max(0.0, r * r - (x - xp) * (x - xp))); }, a,
                  b);
  }

  Node node(int rail, double x) const {
    const double lo = std::max(static_cast<double>(g_.lateral_m - g_.width_m / 2), -static_cast<double>(g_.half_width_m));
    const double hi = std::min(static_cast<double>(g_.lateral_m + g_.width_m / 2), static_cast<double>(g_.half_width_m));
    const Touch across = lo == hi ? Touch{slice(rail, x, lo).value, lo}
                                  : golden([&](double y) { return slice(rail, x, y).value; }, lo, hi);
    Node out;
    if (!(across.value > -0.5)) return out;  // out of reach
    const double y_p = across.at;
    const double x_p = slice(rail, x, y_p).at;
    out.reach = true;
    out.height_m = across.value;
    out.touch_x_m = x_p;
    // The slice normal (x - x_p, h - top) / r tilted across by c'(y_p).
    const double r = radius(y_p);
    const double n_x = (x - x_p) / r, n_z_slice = (across.value - top(rail, x_p, y_p)) / r;
    const double e = 1e-6;
    const double c1 = (crown(y_p + e) - crown(y_p - e)) / (2 * e);
    out.normal_z = n_z_slice / std::sqrt(n_x * n_x + c1 * c1 * n_z_slice * n_z_slice + n_z_slice * n_z_slice);
    // Hertz's constant: an edge (the rail end's cut, the tread's rim, a thin
    // disc) or a line takes the empirical one.
    const double empirical = 3.86e-8 * std::pow(static_cast<double>(g_.radius_m), -0.115);
    out.hertz_constant = empirical;
    const double cut = static_cast<double>(reference::cut_m(g_, rail, y_p));
    const bool at_cut = std::abs(x_p - cut) < 1e-9;
    const bool at_rim = g_.width_m == 0 || std::abs(y_p - lo) < 1e-9 || std::abs(y_p - hi) < 1e-9;
    if (at_cut || at_rim) return out;
    const double kappa = static_cast<double>(g_.conicity);
    const double c2 = (crown(y_p + e) - 2 * crown(y_p) + crown(y_p - e)) / (e * e);
    const double t1 = (top(rail, x_p + e, y_p) - top(rail, x_p - e, y_p)) / (2 * e);
    const double t2 = (top(rail, x_p + e, y_p) - 2 * top(rail, x_p, y_p) + top(rail, x_p - e, y_p)) / (e * e);
    // The gap between the surfaces is A x^2 + B y^2 with A and B half the
    // sums of the two bodies' curvatures along and across (Johnson 4.2).
    RelativeCurvatures k;
    k.along_x_per_m = 0.5 * (1.0 / (r * std::sqrt(1.0 + kappa * kappa)) - t2 / std::pow(1.0 + t1 * t1, 1.5));
    k.across_y_per_m = 0.5 * (-c2 / std::pow(1.0 + c1 * c1, 1.5));  // the cone: none across
    out.ellipse = elliptical_hertz(k, HertzMaterial{});
    if (out.ellipse) out.hertz_constant = out.ellipse->hertz_constant_m_per_N2_3;
    return out;
  }

  const Node& nearest(int rail, double x) const {
    const double u = std::clamp(std::round((x - x0_) / kCell_m), 0.0, static_cast<double>(nodes_[rail].size() - 1));
    return nodes_[rail][static_cast<std::size_t>(u)];
  }

  reference::Geometry g_;
  double x0_;
  std::vector<Node> nodes_[2];
};

}  // namespace railjoint::testing_reference
