#pragma once
// The two rail ends' Hertz contacts as the tests' independent references
// (lumped_track_reference.h, real_surface_slice_reference.h,
// hermite_beam_reference.h) take them: each rail end's touching point along
// the track, approach, normal and Hertz constant, into the vertical forces on
// the wheel. Where the wheel spans the joint the two are coupled through
// sim/rail_end_patch_share.h's spanning_contact: that law is a model input to
// these references, checked on its own against the boundary-element solution
// of one elastic body in tests/sim/rail_end_patch_share_test.cpp, as the
// slice reference takes Hertz's elliptical constant from models/. The
// references check the dynamics around it (the integration, the track, the
// geometry), not the law again.

#include <array>
#include <cmath>
#include <optional>

#include "models/hertz_contact.h"
#include "models/hertz_ellipse.h"
#include "sim/rail_end_patch_share.h"

namespace railjoint::testing_reference {

struct RailEndTouch {
  double x_m = 0.0;            ///< the touching point along the track
  double penetration_m = 0.0;  ///< along the normal (<= 0: not bearing)
  double normal_z = 1.0;       ///< the normal's vertical part
  double hertz_constant = 4.2e-8;  ///< G [m/N^(2/3)]
  /// Hertz's ellipse where the contact is one, else (a line, an edge) the
  /// patch's semi-length along the track is a sphere's sqrt(R delta).
  std::optional<EllipticalHertz> ellipse;
};

/// The modulus that couples the two rail ends, with the steel pair's E*
/// (210 GPa, 0.3 for both, the scenes' default contact.youngs_modulus and
/// poisson_ratio): one half-space under both rail ends at a closed joint;
/// across an end-post gap each rail end is its own body and only the
/// wheel's surface, half the pair's compliance, is shared (2 E*): the force
/// run's assumption (force_contact_geometry.h), taken here as a model input.
inline double reference_coupling_modulus_Pa(bool end_post_gap = false) {
  const HertzMaterial steel;
  // 1 / E* = (1 - nu1^2) / E1 + (1 - nu2^2) / E2 (Johnson 1985, 4.2): 115 GPa.
  const double e_star_Pa = steel.youngs_modulus_Pa / (2.0 * (1.0 - steel.poisson_ratio * steel.poisson_ratio));
  return end_post_gap ? 2.0 * e_star_Pa : e_star_Pa;
}

/// The vertical force each rail end puts on the wheel [N].
inline std::array<double, 2> spanning_forces_z_N(const std::array<RailEndTouch, 2>& touch, double wheel_radius_m,
                                                 double coupling_modulus_Pa = reference_coupling_modulus_Pa()) {
  const auto force_N = [&](int i, double penetration_m) {
    const double ratio = penetration_m / touch[static_cast<std::size_t>(i)].hertz_constant;
    return penetration_m > 0.0 ? ratio * std::sqrt(ratio) : 0.0;
  };
  const auto patch_at = [&](int i, double penetration_m) -> RailEndPatch {
    const RailEndTouch& t = touch[static_cast<std::size_t>(i)];
    if (!(penetration_m > 0.0)) return {t.x_m, 0.0, 0.0};
    const double f = force_N(i, penetration_m);
    const double semi_m =
        t.ellipse ? hertz_patch(*t.ellipse, f).semi_axis_x_m : std::sqrt(wheel_radius_m * penetration_m);
    return {t.x_m, semi_m, f};
  };
  const SpanningContact s =
      spanning_contact({touch[0].penetration_m, touch[1].penetration_m}, patch_at, coupling_modulus_Pa);
  std::array<double, 2> out{};
  for (int i = 0; i < 2; ++i) {
    const auto k = static_cast<std::size_t>(i);
    out[k] = s.share[k] * force_N(i, s.effective_penetration_m[k]) * touch[k].normal_z;
  }
  return out;
}

}  // namespace railjoint::testing_reference
