#pragma once
// Beyond the thesis (its section 7.2.2): Hertz theory for the contact patch
// and the Hertzian pressure over the part of the patch that still bears.
//
// Patch size from the radii: a wheel of rolling radius R_w (curvature along
// the track) on a rail head of crown radius R_c (curvature across it), both
// otherwise straight, pressed together by N. The gap between the unloaded
// surfaces is A x^2 + B y^2 with A = 1/(2 R_w), B = 1/(2 R_c); with the
// contact modulus E* = E / (2 (1 - nu^2)) (same steel both sides) Hertz
// theory (Johnson, Contact Mechanics, 1985, section 4.2) gives an ellipse of
// semi-axes a >= b, eccentricity e = sqrt(1 - b^2/a^2), from
//   B'/A' = [ (a/b)^2 E(e) - K(e) ] / [ K(e) - E(e) ]      (A' <= B' the curvatures along a and b)
//   a^3   = 3 N (K(e) - E(e)) / (2 pi e^2 A' E*)
// with K and E the complete elliptic integrals (Boost.Math), and peak
// pressure p0 = 3 N / (2 pi a b).
//
// Pressure over the bearing part: the Hertzian shape
// p = p_max sqrt(1 - (2x/a)^2 - (2y/b)^2) over the ellipse with full axes
// a, b, kept on the parts of the patch over the two rail ends and scaled so
// that they carry N together. Under the map to the unit disc each rail end
// is a half-plane s < s_in or s > s_out (s: signed distance along the
// mapped cut normal), and the volume of the unit hemisphere over s < t is
// V(t) = (pi/6)(2 + 3t - t^3), so everything is in closed form.

#include <boost/math/policies/policy.hpp>

#include "models/contact_patch.h"
#include "models/end_post_gap.h"

namespace railjoint {

/// The policy of the Hertz solutions' elliptic integrals. Boost evaluates a
/// double's in long double by default (promote_double); a force run solves
/// the eccentricity at every step, and that promotion was a third of a 60E1
/// lumped run's time. Double carries the integrals to a few ulps, far inside
/// the eccentricity's tolerance (hertz_contact.cpp).
using EllipticIntegralPolicy = boost::math::policies::policy<boost::math::policies::promote_double<false>>;

struct HertzMaterial {
  double crown_radius_m = 0.3;        ///< rail-head crown radius R_c, across the track [m] (UIC 60: 300 mm)
  double youngs_modulus_Pa = 210e9;   ///< E of wheel and rail steel [Pa]
  double poisson_ratio = 0.3;         ///< nu of wheel and rail steel [-]
};

struct HertzEllipse {
  double semi_axis_x_m = 0.0;   ///< along the track [m]
  double semi_axis_y_m = 0.0;   ///< across the track [m]
  double eccentricity = 0.0;    ///< sqrt(1 - (minor/major)^2)
  double max_pressure_Pa = 0.0; ///< p0 = 3 N / (2 pi a b) [Pa]
};

/// Hertz ellipse for relative curvatures A along x and B along y [1/m] (gap
/// A x^2 + B y^2), contact modulus E* [Pa] and normal force N [N].
HertzEllipse hertz_ellipse(double curvature_x_per_m, double curvature_y_per_m, double contact_modulus_Pa,
                           double normal_force_N);

/// The wheel on the rail head: A = 1/(2 R_w), B = 1/(2 R_c), E* = E / (2 (1 - nu^2)).
HertzEllipse wheel_on_rail_hertz_ellipse(double wheel_radius_m, const HertzMaterial& material, double normal_force_N);

/// E* = E / (2 (1 - nu^2)) for two bodies of the same material [Pa].
double contact_modulus_Pa(const HertzMaterial& material);

/// The Hertzian pressure over the bearing part of an ellipse patch (full axes
/// a, b) whose front is at x_front, carrying N.
struct HertzianBearing {
  double peak_pressure_Pa = 0.0;    ///< highest pressure anywhere on the bearing part [Pa]
  double scale_pressure_Pa = 0.0;   ///< p_max of the scaled Hertzian shape (reached only if the centre bears) [Pa]
  double force_incoming_N = 0.0;    ///< carried by the rail end the patch comes from [N]
  double force_outgoing_N = 0.0;    ///< carried by the rail end it goes to [N]
};
HertzianBearing hertzian_bearing(const ContactPatch& ellipse, const EndPostGap& gap, double normal_force_N,
                                 double x_front_m);

}  // namespace railjoint
