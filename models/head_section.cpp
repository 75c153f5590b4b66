#include "models/head_section.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

#include "models/rail_head.h"
#include "models/wheel_rail_envelope.h"
#include "models/wheel_tread.h"

namespace railjoint {

HeadSection head_section(const JointParams& joint, const WheelParams& wheel, int samples) {
  assert(samples >= 2);
  // The general model on level rail (no dip, no cut in reach): its support
  // is the resting height, max over the span of c(y) + r(y), and its slice.
  JointParams level = joint;
  level.kind = JointKind::inclined;
  level.beta_rad = 0.0;
  level.gap_m = 0.0;
  level.dip_shape = DipShape::linear;
  const RailSupport rest = rail_support(level, wheel, 0, -joint.length_m / 4.0);
  const LateralSpan span = wheel_span_on_head(joint, wheel);
  const auto point = [&](double y) {
    HeadSectionPoint p;
    p.y_m = y;
    p.head_z_m = head_top_height_m(joint, y);
    const bool on_wheel = y >= span.lo_m && y <= span.hi_m;
    p.tread_z_m = on_wheel ? rest.centre_z_m - tread_radius_m(wheel, y) : std::numeric_limits<double>::quiet_NaN();
    return p;
  };
  HeadSection section;
  for (int i = 0; i < samples; ++i) section.points.push_back(point(-joint.half_width_m + 2.0 * joint.half_width_m * i / (samples - 1)));
  // A cylinder on a flat head touches all along its width: the wheel's own
  // plane stands for that line (any point of it would do).
  const bool line_contact = has_flat_head(joint) && has_cylindrical_tread(wheel);
  section.contact = point(line_contact ? std::clamp(wheel.lateral_m, span.lo_m, span.hi_m) : rest.contact_m.y());
  return section;
}

}  // namespace railjoint
