#pragma once
// The rail head and the wheel's tread across the track on plain rail (no
// dip, no cut): where a crowned head and a conical tread touch. The tread is
// the wheel resting on the head, its centre at the lowest height that does
// not cut it, max over its span of c(y) + r(y) (rail_head.h, wheel_tread.h),
// so at y it lies at that height minus r(y). Thesis section 7.2.1's point:
// the contact sits where the head's slope meets the tread's, about
// -kappa rho on a crown of radius rho under a cone kappa.

#include <vector>

#include "models/parameters.h"

namespace railjoint {

struct HeadSectionPoint {
  double y_m = 0.0;       ///< lateral position [m]
  double head_z_m = 0.0;  ///< the head's top below its crest [m]
  double tread_z_m = 0.0; ///< the tread's lowest line above y [m]; NaN off the wheel's span
};

struct HeadSection {
  std::vector<HeadSectionPoint> points;  ///< `samples` points across the head, -b_t to b_t
  HeadSectionPoint contact;              ///< where the tread touches the head (a cylinder on a flat head: at y_w, on a line)
};

HeadSection head_section(const JointParams& joint, const WheelParams& wheel, int samples);

}  // namespace railjoint
