#pragma once
// An exact reference for the kinematic momentum jump, written in the tests and
// independent of models/ (which solves slice profiles): the wheel is "glued"
// to the rails, so its centre height h(x) is the upper envelope of the
// heights at which it touches each rail, and the jump is M v times the rise
// of the slope of that envelope where the outgoing rail takes over.
//
// Derivation. A wheel (thin disc or cylinder, axle along y, spanning lateral
// positions [y_a, y_b]) touches a rail top z = m x + c that covers
// x <= e(y) (incoming) or x >= e(y) (outgoing) for y in the span. The
// centre height is the largest p_z + sqrt(R^2 - (p_x - x)^2) over the
// rail's top points p. For one rail this depends on p_x alone:
//   g(p_x) = m p_x + c + sqrt(R^2 - (p_x - x)^2),
// which is concave, with its unconstrained maximum at the tangent point
// p_x = x + R m / sqrt(1 + m^2). So the touching point is the tangent point
// clamped into the rail's extent over the span: for the incoming rail to
// x <= max_y e_0(y), for the outgoing rail to x >= min_y e_1(y). Clamped, it
// is the rail's cut edge (the corner the wheel pivots about or strikes). The
// slope of h for that rail is then dh/dx = (p_x - x) / sqrt(R^2 - (p_x - x)^2)
// (= m on the plane). The two rails' heights cross once; the jump is
//   Delta p = M v (h_1'(x*) - h_0'(x*)),  h_0(x*) = h_1(x*),
// found here by bisection. Examples it reproduces (checked in
// exact_jump_reference_test.cpp): scenario 1, 2 M v tan(beta/2); a step up,
// M v tan(alpha) with cos(alpha) = (R - u0)/R.
//
// Rail ends (the thesis's coordinates, models/DESIGN.md "Coordinates and symbols"): the cut is
// x_cut(y) = y cot(theta); an end-post gap g (normal to the cut) moves the
// incoming end back and the outgoing end forward by g / (2 sin theta) each
// (g / 2 for a step joint, whose cut is square).

#include <algorithm>
#include <cmath>

#include "models/parameters.h"

namespace railjoint::testing_reference {

struct ExactJump {
  double jump_Ns = 0.0;
  double impact_x_m = 0.0;       ///< wheel centre x where the outgoing rail takes over [m]
  double struck_x_m = 0.0;       ///< x of the touching point on the outgoing rail there [m]
  double slope_before = 0.0;     ///< dh/dx of the centre just before [-]
  double slope_after = 0.0;      ///< just after [-]
  bool on_landing = false;       ///< the incoming rail's edge carried the wheel before (a step down)
};

/// The lateral span of the wheel's contact: a thin disc is one slice.
struct WheelSpan {
  double y_min_m;
  double y_max_m;
};

/// Where the wheel touches each rail and at what centre height, for centre
/// position x (the derivation above).
class ExactRails {
 public:
  struct Touch {
    double height_m;  ///< centre height when touching this rail
    double slope;     ///< its d/dx
    double point_x_m;
    bool edge;        ///< at the rail's cut edge (clamped)
  };

  ExactRails(const JointParams& joint, const WheelParams& wheel, WheelSpan span) : R_(wheel.radius_m) {
    const bool step = joint.kind == JointKind::step;
    const double t = step ? 0.0 : std::tan(joint.beta_rad / 2.0);
    const double cot = step ? 0.0 : std::cos(joint.theta_rad) / std::sin(joint.theta_rad);
    const double cot_or_zero = std::abs(cot) < 1e-15 ? 0.0 : cot;
    const double shift = step ? joint.gap_m / 2.0 : joint.gap_m / (2.0 * std::sin(joint.theta_rad));
    const double y_lo = std::max(span.y_min_m, -joint.half_width_m);
    const double y_hi = std::min(span.y_max_m, joint.half_width_m);
    // Rail tops z = m x + c and their cut edges over the span (cot >= 0 for theta <= 90 deg).
    m0_ = -t;
    c0_ = 0.0;
    m1_ = t;
    c1_ = step ? joint.step_height_m : 0.0;
    end0_ = y_hi * cot_or_zero - shift;    // incoming rail reaches x <= end0 somewhere in the span
    start1_ = y_lo * cot_or_zero + shift;  // outgoing rail starts at x >= start1 somewhere
  }

  Touch incoming(double x) const {
    const double tangent = x + R_ * m0_ / std::sqrt(1.0 + m0_ * m0_);
    return touch(m0_, c0_, x, std::min(tangent, end0_), tangent > end0_);
  }
  Touch outgoing(double x) const {
    const double tangent = x + R_ * m1_ / std::sqrt(1.0 + m1_ * m1_);
    return touch(m1_, c1_, x, std::max(tangent, start1_), tangent < start1_);
  }
  /// Where the two heights cross: the outgoing rail is below the incoming one
  /// far before the joint and above it far after; bisected within R/2 of the ends.
  double crossing_x_m() const {
    double lo = std::min(end0_, start1_) - 0.5 * R_;
    double hi = std::max(end0_, start1_) + 0.5 * R_;
    for (int i = 0; i < 200 && hi - lo > 0; ++i) {
      const double mid = 0.5 * (lo + hi);
      if (outgoing(mid).height_m - incoming(mid).height_m < 0) {
        lo = mid;
      } else {
        hi = mid;
      }
    }
    return 0.5 * (lo + hi);
  }

 private:
  Touch touch(double m, double c, double x, double p_x, bool edge) const {
    const double u = p_x - x;
    const double root = std::sqrt(std::max(R_ * R_ - u * u, 0.0));
    return Touch{m * p_x + c + root, u / root, p_x, edge};
  }

  double R_;
  double m0_ = 0, c0_ = 0, m1_ = 0, c1_ = 0, end0_ = 0, start1_ = 0;
};

inline ExactJump exact_jump(const JointParams& joint, const WheelParams& wheel, WheelSpan span) {
  const ExactRails rails(joint, wheel, span);
  const double x = rails.crossing_x_m();
  const ExactRails::Touch before = rails.incoming(x);
  const ExactRails::Touch after = rails.outgoing(x);
  ExactJump out;
  out.impact_x_m = x;
  out.struck_x_m = after.point_x_m;
  out.slope_before = before.slope;
  out.slope_after = after.slope;
  out.on_landing = before.edge;
  out.jump_Ns = wheel.mass_kg * wheel.speed_m_per_s * (after.slope - before.slope);
  return out;
}

/// A thin disc at wheel.lateral_m, or a cylinder of wheel.width_m centred there.
inline ExactJump exact_jump(const JointParams& joint, const WheelParams& wheel) {
  const double half = 0.5 * wheel.width_m;
  return exact_jump(joint, wheel, WheelSpan{wheel.lateral_m - half, wheel.lateral_m + half});
}

/// The flight after a strike on the outgoing rail's corner (scenario 2, a
/// step up) when the load cannot hold the wheel on the corner: it leaves
/// the strike point with the corner's tangent velocity, v (slope_after), and
/// flies under g = W / M (horizontal speed held) until its centre is back
/// at the outgoing rail's touching height, the first x with
///   h(x*) + v s (x - x*) / v - g ((x - x*) / v)^2 / 2 = h_1(x).
/// The landing's jump is M v (h_1'(x) - z'(x)), z' the parabola's slope.
struct ExactLanding {
  double landing_x_m = 0.0;
  double flight_s = 0.0;
  double jump_Ns = 0.0;
};

inline ExactLanding exact_landing_after_strike(const JointParams& joint, const WheelParams& wheel, WheelSpan span,
                                               double vertical_load_N) {
  const ExactRails rails(joint, wheel, span);
  const double x_strike = rails.crossing_x_m();
  const ExactRails::Touch strike = rails.outgoing(x_strike);
  const double v = wheel.speed_m_per_s;
  const double g = vertical_load_N / wheel.mass_kg;
  const auto above = [&](double x) {
    const double t = (x - x_strike) / v;
    return strike.height_m + v * strike.slope * t - 0.5 * g * t * t - rails.outgoing(x).height_m;
  };
  // March in 0.1 mm steps (the parabola leaves the corner's arc above it),
  // then bisect.
  double lo = x_strike + 1e-4;
  double hi = lo;
  while (above(hi) > 0.0 && hi < x_strike + 100.0) {
    lo = hi;
    hi += 1e-4;
  }
  for (int i = 0; i < 200 && hi - lo > 0; ++i) {
    const double mid = 0.5 * (lo + hi);
    (above(mid) > 0.0 ? lo : hi) = mid;
  }
  ExactLanding out;
  out.landing_x_m = hi;
  out.flight_s = (hi - x_strike) / v;
  const double parabola_zdot = v * strike.slope - g * out.flight_s;
  out.jump_Ns = wheel.mass_kg * (v * rails.outgoing(hi).slope - parabola_zdot);
  return out;
}

}  // namespace railjoint::testing_reference
