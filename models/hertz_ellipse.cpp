#include "models/hertz_ellipse.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <boost/math/special_functions/ellint_1.hpp>

namespace railjoint {

RelativeCurvatures relative_curvatures(const ContactCurvatures& k) {
  return {0.5 * (k.wheel_along_x_per_m + k.rail_along_x_per_m), 0.5 * (k.wheel_across_y_per_m + k.rail_across_y_per_m)};
}

std::optional<EllipticalHertz> elliptical_hertz(const RelativeCurvatures& curvatures, const HertzMaterial& material) {
  const double A = curvatures.along_x_per_m;
  const double B = curvatures.across_y_per_m;
  if (!(A > 0.0) || !(B > 0.0) || !std::isfinite(A) || !std::isfinite(B)) return std::nullopt;
  EllipticalHertz out;
  out.curvatures = curvatures;
  out.contact_modulus_Pa = contact_modulus_Pa(material);
  HertzEllipse unit;
  try {
    unit = hertz_ellipse(A, B, out.contact_modulus_Pa, 1.0);
  } catch (const std::invalid_argument&) {
    return std::nullopt;  // b/a below 1e-6: a line contact in all but name
  }
  out.eccentricity = unit.eccentricity;
  const double major_m = std::max(unit.semi_axis_x_m, unit.semi_axis_y_m);
  out.hertz_constant_m_per_N2_3 =
      3.0 * boost::math::ellint_1(unit.eccentricity, EllipticIntegralPolicy()) / (2.0 * std::numbers::pi * major_m * out.contact_modulus_Pa);
  return out;
}

HertzPatch hertz_patch(const EllipticalHertz& hertz, double load_N) {
  HertzPatch patch;
  if (!(load_N > 0.0)) return patch;
  const HertzEllipse e = hertz_ellipse(hertz.curvatures.along_x_per_m, hertz.curvatures.across_y_per_m,
                                       hertz.contact_modulus_Pa, load_N);
  patch.semi_axis_x_m = e.semi_axis_x_m;
  patch.semi_axis_y_m = e.semi_axis_y_m;
  patch.max_pressure_Pa = e.max_pressure_Pa;
  patch.approach_m = hertz.hertz_constant_m_per_N2_3 * std::cbrt(load_N * load_N);
  return patch;
}

}  // namespace railjoint
