#include "models/wheel_rail_envelope.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <limits>

#include <boost/math/tools/toms748_solve.hpp>

#include "models/dip_profile.h"
#include "models/inclined_joint.h"
#include "models/rail_head.h"
#include "models/rail_top.h"
#include "models/slice_profile.h"
#include "models/wheel_tread.h"

namespace railjoint {

namespace {

// A root search's bracket is done when its ends are neighbours in double
// precision, or within 1e-18 m of each other where they straddle 0.
bool bracket_closed(double a, double b) {
  return std::abs(b - a) <= 2.0 * std::numeric_limits<double>::epsilon() * std::max(std::abs(a), std::abs(b)) ||
         std::abs(b - a) <= 1e-18;
}

// The root of a function that falls through zero on [a, b] (f(a) > 0 > f(b)),
// to the last bits: TOMS 748, which keeps a bracket and so tolerates the
// kinks and the jump where a rail comes into reach.
template <typename F>
std::pair<double, double> falling_root(F f, double a, double b, double f_a, double f_b) {
  std::uintmax_t iterations = 200;
  return boost::math::tools::toms748_solve(f, a, b, f_a, f_b, [](double u, double v) { return bracket_closed(u, v); },
                                           iterations);
}

// The general model's constants for one joint and wheel, worked out once.
class Envelope {
 public:
  Envelope(const JointParams& joint, const WheelParams& wheel) : joint_(joint), wheel_(wheel) {
    linear_rails_ = joint.kind == JointKind::step || joint.dip_shape == DipShape::linear;
    measured_ = joint.rail_profile == RailProfile::measured || wheel.measured_tread != nullptr;
    cut_slope_ = joint.kind == JointKind::step || is_square_joint(joint.theta_rad)
                     ? 0.0
                     : std::cos(joint.theta_rad) / std::sin(joint.theta_rad);
    span_ = wheel_span_on_head(joint, wheel);
  }

  // x interval of rail 0 or 1 in slice y: from the far end to the cut, or
  // from the cut to the far end.
  std::pair<double, double> rail_interval(int rail, double y) const {
    const double half_length = joint_.length_m / 2.0;
    return rail == 0 ? std::pair{-half_length, cut_x_m(joint_, y, 0)} : std::pair{cut_x_m(joint_, y, 1), half_length};
  }

  RailSupport slice(int rail, double y, double x) const {
    const double r = tread_radius_m(wheel_, y);
    const auto [a, b] = rail_interval(rail, y);
    const double cut = rail == 0 ? b : a;
    const double crown = head_top_height_m(joint_, y);
    RailSupport out;
    double contact_x = 0.0, contact_z = 0.0, over_contact = 0.0;
    if (linear_rails_) {
      // One straight piece per rail end: the closed form of slice_profile.h.
      const ProfileSegment segment{{a, rail_surface_height_m(joint_, rail, a)}, {b, rail_surface_height_m(joint_, rail, b)}};
      const SegmentSupport s = segment_support(segment, r, x);
      if (!std::isfinite(s.centre_z_m)) return out;
      contact_x = s.contact_m.x();
      contact_z = s.contact_m.y();
      over_contact = s.centre_z_m - contact_z;
      out.slope = s.slope;
      out.at_cut_edge = s.at_corner && contact_x == cut;
    } else {
      // A curved (concave) dip: d(x') + sqrt(r^2 - (x - x')^2) is concave in
      // x', its derivative falls from +inf at x - r to -inf at x + r; the
      // highest point of the bracket is where it crosses zero, or an end of
      // the rail within reach.
      const double lo = std::max(a, x - r);
      const double hi = std::min(b, x + r);
      if (!(lo <= hi)) return out;
      const auto derivative = [&](double xp) {
        const double u = x - xp;
        return rail_surface_slope(joint_, rail, xp) + u / std::sqrt((r - u) * (r + u));
      };
      if (derivative(hi) >= 0.0) {
        contact_x = hi;
      } else if (derivative(lo) <= 0.0) {
        contact_x = lo;
      } else {
        // Bisection: the ends may be infinite, which TOMS 748 cannot interpolate.
        double down = lo, up = hi;
        while (!bracket_closed(down, up)) {
          const double mid = 0.5 * (down + up);
          if (mid <= down || mid >= up) break;
          (derivative(mid) > 0.0 ? down : up) = mid;
        }
        contact_x = 0.5 * (down + up);
      }
      const double u = x - contact_x;
      contact_z = rail_surface_height_m(joint_, rail, contact_x);
      over_contact = std::sqrt(std::max(0.0, (r - u) * (r + u)));
      out.slope = -u / over_contact;
      out.at_cut_edge = contact_x == cut;
    }
    out.centre_z_m = crown + contact_z + over_contact;
    out.contact_m = {contact_x, y, crown + contact_z};
    return out;
  }

  // dS/dy of a slice's support (the header's S); where the rail is out of the
  // slice's reach, the sign that leads back into reach. 0 where it is below
  // the round-off of its terms: no search can place the maximum better, and
  // a root search stops there instead of chasing the noise's sign.
  double slope_in_y(int rail, double y, double x, const RailSupport& s) const {
    const double dr = tread_radius_slope(wheel_, y);
    if (!std::isfinite(s.centre_z_m)) return rail == 0 ? cut_slope_ + dr : dr - cut_slope_;
    const double over_contact = s.centre_z_m - s.contact_m.z();
    const double crown_term = head_top_slope(joint_, y);
    const double tread_term = tread_radius_m(wheel_, y) * dr / over_contact;
    double edge_term = 0.0;
    if (s.at_cut_edge && cut_slope_ != 0.0) {
      const double xc = s.contact_m.x();
      edge_term = cut_slope_ * (rail_surface_slope(joint_, rail, xc) + (x - xc) / over_contact);
    }
    const double d = crown_term + tread_term + edge_term;
    const double noise = 8.0 * std::numeric_limits<double>::epsilon() *
                         (std::abs(crown_term) + std::abs(tread_term) + std::abs(edge_term));
    return std::abs(d) <= noise ? 0.0 : d;
  }

  RailSupport support(int rail, double x) const {
    if (span_.hi_m == span_.lo_m) return slice(rail, span_.lo_m, x);
    if (measured_) return support_not_concave(rail, x);
    return support_on(rail, x, span_.lo_m, span_.hi_m);
  }

  // The highest support over [lo, hi] of a slice support that is concave
  // there: the root of dS/dy, or an end.
  RailSupport support_on(int rail, double x, double lo, double hi) const {
    const RailSupport at_lo = slice(rail, lo, x);
    const double d_lo = slope_in_y(rail, lo, x, at_lo);
    if (!(d_lo > 0.0)) return at_lo;
    const RailSupport at_hi = slice(rail, hi, x);
    const double d_hi = slope_in_y(rail, hi, x, at_hi);
    if (!(d_hi < 0.0)) return at_hi;
    const auto d = [&](double y) { return slope_in_y(rail, y, x, slice(rail, y, x)); };
    const auto [a, b] = falling_root(d, lo, hi, d_lo, d_hi);
    const RailSupport left = slice(rail, a, x);
    const RailSupport right = slice(rail, b, x);
    return right.centre_z_m > left.centre_z_m ? right : left;
  }

  // A measured head or tread need not keep S concave: the best of 64 slices
  // across the span first, then the root search between its neighbours (a
  // bump narrower than the span / 64 could hide; measured profiles are
  // sampled far coarser than that). The slices stay inside the span: lo +
  // (hi - lo) can round an ulp past hi, and a measured tread that ends
  // where the wheel does is read past its last point there.
  RailSupport support_not_concave(int rail, double x) const {
    constexpr int kSlices = 64;
    const auto y_at = [&](int i) {
      return std::min(span_.hi_m, span_.lo_m + (span_.hi_m - span_.lo_m) * i / kSlices);
    };
    int best = 0;
    double best_z = -std::numeric_limits<double>::infinity();
    for (int i = 0; i <= kSlices; ++i) {
      const double z = slice(rail, y_at(i), x).centre_z_m;
      if (z > best_z) {
        best_z = z;
        best = i;
      }
    }
    return support_on(rail, x, y_at(std::max(0, best - 1)), y_at(std::min(kSlices, best + 1)));
  }

  EnvelopeContact contact() const {
    // g(x) = outgoing - incoming support: < 0 while the incoming rail carries
    // the wheel, > 0 once the outgoing one does; the largest slice radius
    // either side of the cut's reach over the span brackets the change.
    double r_max = 0.0, cut_in_min = std::numeric_limits<double>::infinity();
    double cut_out_max = -std::numeric_limits<double>::infinity();
    for (const double y : {span_.lo_m, span_.hi_m}) {
      r_max = std::max(r_max, tread_radius_m(wheel_, y));
      cut_in_min = std::min(cut_in_min, cut_x_m(joint_, y, 0));
      cut_out_max = std::max(cut_out_max, cut_x_m(joint_, y, 1));
    }
    // Out of reach counts as a metre below: g stays negative there, which is
    // all a bracketing search needs.
    // Below the heights' round-off g is 0: the crossing is found as well as
    // the heights can place it (the tests' calibration: eps R / ds).
    const auto height = [](const RailSupport& s) { return std::isfinite(s.centre_z_m) ? s.centre_z_m : -1.0; };
    const auto g = [&](double x) {
      const double out = height(support(1, x)), in = height(support(0, x));
      const double noise = 8.0 * std::numeric_limits<double>::epsilon() * std::max(std::abs(out), std::abs(in));
      return std::abs(out - in) <= noise ? 0.0 : out - in;
    };
    const double lo = cut_in_min - r_max;
    const double hi = cut_out_max + r_max;
    const double g_lo = g(lo), g_hi = g(hi);
    assert(g_lo < 0.0 && g_hi > 0.0);
    const auto [a, b] = falling_root([&](double x) { return -g(x); }, lo, hi, -g_lo, -g_hi);
    EnvelopeContact contact;
    contact.centre_x_m = 0.5 * (a + b);
    contact.incoming = support(0, contact.centre_x_m);
    contact.outgoing = support(1, contact.centre_x_m);
    contact.centre_z_m = std::max(contact.incoming.centre_z_m, contact.outgoing.centre_z_m);
    return contact;
  }

 private:
  JointParams joint_;
  WheelParams wheel_;
  bool linear_rails_ = true;
  bool measured_ = false;  // a measured head or tread: S need not be concave in y
  double cut_slope_ = 0.0;  // d(cut x)/dy [-]
  LateralSpan span_;
};

}  // namespace

LateralSpan wheel_span_on_head(const JointParams& joint, const WheelParams& wheel) {
  return {std::max(wheel.lateral_m - wheel.width_m / 2.0, -joint.half_width_m),
          std::min(wheel.lateral_m + wheel.width_m / 2.0, joint.half_width_m)};
}

RailSupport rail_support(const JointParams& joint, const WheelParams& wheel, int rail, double centre_x_m) {
  assert(rail == 0 || rail == 1);
  return Envelope(joint, wheel).support(rail, centre_x_m);
}

RailSupport slice_rail_support(const JointParams& joint, const WheelParams& wheel, int rail, double y_m,
                               double centre_x_m) {
  assert(rail == 0 || rail == 1);
  return Envelope(joint, wheel).slice(rail, y_m, centre_x_m);
}

EnvelopeContact solve_envelope_contact(const JointParams& joint, const WheelParams& wheel) {
  return Envelope(joint, wheel).contact();
}

bool has_thesis_geometry(const JointParams& joint, const WheelParams& wheel) {
  return has_flat_head(joint) && has_cylindrical_tread(wheel) && joint.dip_shape == DipShape::linear;
}

}  // namespace railjoint
