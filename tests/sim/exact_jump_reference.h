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
// Rail ends (the thesis's coordinates, DESIGN.md): the cut is
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

inline ExactJump exact_jump(const JointParams& joint, const WheelParams& wheel, WheelSpan span) {
  const double R = wheel.radius_m;
  const bool step = joint.kind == JointKind::step;
  const double t = step ? 0.0 : std::tan(joint.beta_rad / 2.0);
  const double cot = step ? 0.0 : std::cos(joint.theta_rad) / std::sin(joint.theta_rad);
  const double cot_or_zero = std::abs(cot) < 1e-15 ? 0.0 : cot;
  const double shift = step ? joint.gap_m / 2.0 : joint.gap_m / (2.0 * std::sin(joint.theta_rad));
  const double y_lo = std::max(span.y_min_m, -joint.half_width_m);
  const double y_hi = std::min(span.y_max_m, joint.half_width_m);
  // Rail tops z = m x + c and their cut edges over the span (cot >= 0 for theta <= 90 deg).
  const double m0 = -t, c0 = 0.0, m1 = t, c1 = step ? joint.step_height_m : 0.0;
  const double end0 = y_hi * cot_or_zero - shift;    // incoming rail reaches x <= end0 somewhere in the span
  const double start1 = y_lo * cot_or_zero + shift;  // outgoing rail starts at x >= start1 somewhere
  struct Touch {
    double height_m;
    double slope;
    double point_x_m;
    bool edge;
  };
  const auto touch = [R](double m, double c, double x, double p_x, bool edge) {
    const double u = p_x - x;
    const double root = std::sqrt(std::max(R * R - u * u, 0.0));
    return Touch{m * p_x + c + root, u / root, p_x, edge};
  };
  const auto incoming = [&](double x) {
    const double tangent = x + R * m0 / std::sqrt(1.0 + m0 * m0);
    return touch(m0, c0, x, std::min(tangent, end0), tangent > end0);
  };
  const auto outgoing = [&](double x) {
    const double tangent = x + R * m1 / std::sqrt(1.0 + m1 * m1);
    return touch(m1, c1, x, std::max(tangent, start1), tangent < start1);
  };
  // The outgoing rail is below the incoming one far before the joint and
  // above it far after: bisect on the difference within R/2 of the ends.
  double lo = std::min(end0, start1) - 0.5 * R;
  double hi = std::max(end0, start1) + 0.5 * R;
  for (int i = 0; i < 200 && hi - lo > 0; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (outgoing(mid).height_m - incoming(mid).height_m < 0) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  const double x = 0.5 * (lo + hi);
  const Touch before = incoming(x);
  const Touch after = outgoing(x);
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

}  // namespace railjoint::testing_reference
