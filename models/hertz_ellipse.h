#pragma once
// Hertz's elliptical point contact of a wheel on a rail head, from the two
// bodies' principal curvatures at the touching point (Johnson, Contact
// Mechanics, 1985, section 4.2; the thesis's recommendation 7.2.1: a
// Hertzian contact instead of a point or line contact).
//
// The wheel's axle lies along y and the head runs along x, so both bodies'
// principal directions are x and y and the gap between the unloaded
// surfaces near the touching point is A x^2 + B y^2 with
//   A = (k_wheel_x + k_rail_x) / 2,   B = (k_wheel_y + k_rail_y) / 2,
// k the normal curvatures, convex positive: along x the wheel's rolling
// circle (cos(phi) / r by Meusnier, phi the tread's tilt, r the slice's
// radius) and the dip's bend (a dip droops, so the rail top is convex along
// x: k_rail_x = -d''(x) >= 0); across, the tread's own curvature (0 for a
// cone, negative for a hollow tread) and the head's transverse curvature
// (1/300, 1/80, 1/13 mm on 60E1). Hertz's ellipse (hertz_contact.h) then
// gives the semi-axes and p0 = 3 P / (2 pi a b), and the approach of the
// two bodies' far points is delta = p0 b K(e) / E* (Johnson section 3.4, the
// displacement under the ellipse's pressure) = 3 P K(e) / (2 pi a E*), a the major semi-axis. As a
// grows as P^(1/3), delta = G P^(2/3) with
//   G = 3 K(e) / (2 pi a_1 E*),   a_1 the major semi-axis under 1 N.
// A line contact (B = 0: a cylinder or cone on the flat head) or an edge
// (the rail's cut: k_rail_x infinite) has no such constant: there the
// caller keeps the empirical law (sim/hertz_law.h), which this file says by
// returning nothing.

#include <optional>

#include "models/hertz_contact.h"

namespace railjoint {

/// The relative curvatures of the gap A x^2 + B y^2 [1/m].
struct RelativeCurvatures {
  double along_x_per_m = 0.0;   ///< A
  double across_y_per_m = 0.0;  ///< B
};

/// The principal normal curvatures of the two surfaces at the touching point,
/// convex positive [1/m].
struct ContactCurvatures {
  double wheel_along_x_per_m = 0.0;  ///< the rolling circle's, cos(phi) / r
  double wheel_across_y_per_m = 0.0; ///< the tread's transverse curvature (0 on a cone)
  double rail_along_x_per_m = 0.0;   ///< the dip's bend, -d''(x) (0 on a straight rail)
  double rail_across_y_per_m = 0.0;  ///< the head's transverse curvature (0 on the flat head)
};

RelativeCurvatures relative_curvatures(const ContactCurvatures& k);

/// Hertz's elliptical contact at one touching point.
struct EllipticalHertz {
  double hertz_constant_m_per_N2_3 = 0.0;  ///< G in delta = G P^(2/3)
  double eccentricity = 0.0;               ///< sqrt(1 - (b/a)^2)
  RelativeCurvatures curvatures;
  double contact_modulus_Pa = 0.0;          ///< E* = E / (2 (1 - nu^2))
};

/// Hertz's constant for the curvatures, or nothing where the contact is not
/// an ellipse: a curvature <= 0 (a line contact, a conforming hollow) or
/// not finite (an edge), or a ratio beyond b/a = 1e-6.
std::optional<EllipticalHertz> elliptical_hertz(const RelativeCurvatures& curvatures, const HertzMaterial& material);

/// The patch under a load P > 0 [N].
struct HertzPatch {
  double semi_axis_x_m = 0.0;    ///< along the track
  double semi_axis_y_m = 0.0;    ///< across it
  double max_pressure_Pa = 0.0;  ///< p0 = 3 P / (2 pi a b)
  double approach_m = 0.0;       ///< G P^(2/3)
};
HertzPatch hertz_patch(const EllipticalHertz& hertz, double load_N);

}  // namespace railjoint
