#include "models/hertz_contact.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <stdexcept>

#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/ellint_d.hpp>
#include <boost/math/tools/roots.hpp>

namespace railjoint {

namespace {

constexpr double kPi = std::numbers::pi;

// [(1/k^2) E(e) - K(e)] / [K(e) - E(e)], k^2 = 1 - e^2: the curvature ratio
// B'/A' >= 1 that an ellipse of eccentricity e answers. Written with
// D(e) = (K - E) / e^2 (Boost's ellint_d) it has no cancellation as e -> 0:
// K - E = e^2 D and (1/k^2) E - K = e^2 (K - D) / k^2, so the ratio is
// (K - D) / (k^2 D), 1 at e = 0 (K = pi/2, D = pi/4).
double curvature_ratio(double e) {
  const double K = boost::math::ellint_1(e, EllipticIntegralPolicy());
  const double D = boost::math::ellint_d(e, EllipticIntegralPolicy());
  return (K - D) / ((1.0 - e * e) * D);
}

// Largest eccentricity searched: (b/a)^2 = 1e-12, a ratio of curvatures
// far beyond any wheel on a rail (~1e17).
const double kMaxEccentricity = std::sqrt(1.0 - 1e-12);
// Its curvature ratio, once (a function's static: no order among files' statics).
double max_curvature_ratio() {
  static const double ratio = curvature_ratio(kMaxEccentricity);
  return ratio;
}

// V(t): volume of the unit hemisphere z = sqrt(1 - x^2 - y^2) over x < t.
double hemisphere_volume_below(double t) {
  t = std::clamp(t, -1.0, 1.0);
  return kPi / 6.0 * (2.0 + 3.0 * t - t * t * t);
}

}  // namespace

double contact_modulus_Pa(const HertzMaterial& material) {
  return material.youngs_modulus_Pa / (2.0 * (1.0 - material.poisson_ratio * material.poisson_ratio));
}

HertzEllipse hertz_ellipse(double curvature_x_per_m, double curvature_y_per_m, double contact_modulus, double N) {
  if (!(curvature_x_per_m > 0.0) || !(curvature_y_per_m > 0.0) || !(contact_modulus > 0.0) || !(N > 0.0)) {
    throw std::invalid_argument("hertz_ellipse: curvatures, modulus and force must be positive");
  }
  const double small = std::min(curvature_x_per_m, curvature_y_per_m);
  const double ratio = std::max(curvature_x_per_m, curvature_y_per_m) / small;
  if (ratio > max_curvature_ratio()) {
    throw std::invalid_argument("hertz_ellipse: curvature ratio beyond a contact ellipse (b/a < 1e-6)");
  }
  double e = 0.0;  // equal curvatures: a circle
  if (ratio > 1.0) {
    const auto f = [ratio](double x) { return curvature_ratio(x) - ratio; };
    // A bracket from the approximation b/a ~ (A'/B')^(2/3) (Johnson 1985,
    // 4.2), which falls short of the exact b/a by 3e-4 at a ratio of 1.6, 1 %
    // at 5 and more beyond (mpmath): [0.999, 1.02] times it holds up to a ratio
    // of about 5, where every wheel on a rail head's crown lies, and the
    // search needs a third of the integrals of one across [0, e_max] (a force
    // run solves this at every step). It depends on the ratio alone, so the
    // same curvatures give the same bits wherever they are asked.
    const double axis_ratio = std::pow(ratio, -2.0 / 3.0);
    const auto eccentricity_of = [](double b_over_a) { return std::sqrt(1.0 - std::min(b_over_a * b_over_a, 1.0)); };
    double lo_e = eccentricity_of(std::min(1.02 * axis_ratio, 1.0));
    double hi_e = std::min(eccentricity_of(0.999 * axis_ratio), kMaxEccentricity);
    double f_lo = f(lo_e), f_hi = f(hi_e);
    if (!(f_lo <= 0.0 && f_hi >= 0.0)) {  // the approximation missed: the whole range
      lo_e = 0.0;
      hi_e = kMaxEccentricity;
      f_lo = 1.0 - ratio;
      f_hi = max_curvature_ratio() - ratio;
    }
    std::uintmax_t iterations = 200;
    const auto [lo, hi] = boost::math::tools::toms748_solve(f, lo_e, hi_e, f_lo, f_hi,
                                                            boost::math::tools::eps_tolerance<double>(50), iterations);
    e = 0.5 * (lo + hi);
  }
  // a^3 = 3 N (K - E) / (2 pi e^2 A' E*) = 3 N D(e) / (2 pi A' E*); at e = 0, 3 N / (8 A' E*).
  const double major_m = std::cbrt(3.0 * N * boost::math::ellint_d(e, EllipticIntegralPolicy()) / (2.0 * kPi * small * contact_modulus));
  const double minor_m = major_m * std::sqrt(1.0 - e * e);
  HertzEllipse ellipse;
  ellipse.eccentricity = e;
  // The long axis lies along the smaller curvature.
  ellipse.semi_axis_x_m = curvature_x_per_m <= curvature_y_per_m ? major_m : minor_m;
  ellipse.semi_axis_y_m = curvature_x_per_m <= curvature_y_per_m ? minor_m : major_m;
  ellipse.max_pressure_Pa = 3.0 * N / (2.0 * kPi * major_m * minor_m);
  return ellipse;
}

HertzEllipse wheel_on_rail_hertz_ellipse(double wheel_radius_m, const HertzMaterial& material, double N) {
  return hertz_ellipse(1.0 / (2.0 * wheel_radius_m), 1.0 / (2.0 * material.crown_radius_m), contact_modulus_Pa(material), N);
}

HertzianBearing hertzian_bearing(const ContactPatch& ellipse, const EndPostGap& gap, double N, double x_front_m) {
  const Eigen::Vector2d n = cut_normal(gap);
  const double half_a = ellipse.length_m / 2.0;
  const double half_b = ellipse.width_m / 2.0;
  // The cut's normal through the map to the unit disc: distances divide by h.
  const double h = std::hypot(half_a * n.x(), half_b * n.y());
  const double centre = n.dot(patch_centre_m(ellipse, x_front_m));
  const double s_in = (0.0 - centre) / h;        // incoming rail end: s < s_in
  const double s_out = (gap.gap_m - centre) / h;  // outgoing rail end: s > s_out
  const double volume_in = hemisphere_volume_below(s_in);
  const double volume_out = hemisphere_volume_below(1.0) - hemisphere_volume_below(s_out);
  const double volume = volume_in + volume_out;  // of the unit hemisphere over the bearing part

  HertzianBearing bearing;
  bearing.scale_pressure_Pa = N / (half_a * half_b * volume);
  bearing.force_incoming_N = N * volume_in / volume;
  bearing.force_outgoing_N = N * volume_out / volume;
  // The highest point of the shape on the bearing part: the centre, or the
  // bearing point nearest to it (on the cut line nearer the centre).
  const bool centre_over_gap = s_in < 0.0 && s_out > 0.0;
  const double r_min = centre_over_gap ? std::min(-s_in, s_out) : 0.0;
  bearing.peak_pressure_Pa = bearing.scale_pressure_Pa * std::sqrt(std::max(0.0, 1.0 - r_min * r_min));
  return bearing;
}

}  // namespace railjoint
