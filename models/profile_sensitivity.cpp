#include "models/profile_sensitivity.h"

#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

#include "models/impact_prediction.h"
#include "models/profile_curve.h"

namespace railjoint {

std::optional<ProfileSensitivity> profile_sensitivity(const JointParams& joint, const WheelParams& wheel,
                                                      double jump_Ns) {
  const auto smoothed = [](const std::shared_ptr<const ProfileCurve>& curve) {
    return curve && curve->smoothing().tolerance_m > 0.0;
  };
  if (!smoothed(joint.measured_head) && !smoothed(wheel.measured_tread)) return std::nullopt;
  JointParams raw_joint = joint;
  WheelParams raw_wheel = wheel;
  if (smoothed(joint.measured_head)) raw_joint.measured_head = std::make_shared<const ProfileCurve>(joint.measured_head->unsmoothed());
  if (smoothed(wheel.measured_tread)) {
    raw_wheel.measured_tread = std::make_shared<const ProfileCurve>(wheel.measured_tread->unsmoothed());
    raw_wheel.radius_m = raw_wheel.measured_tread->value_m(0.0);
  }
  ProfileSensitivity s;
  s.jump_Ns = jump_Ns;
  try {
    s.jump_unsmoothed_Ns = predict_impact(raw_joint, raw_wheel).impulse.exact_Ns;
    s.relative_change = jump_Ns / s.jump_unsmoothed_Ns - 1.0;
  } catch (const std::exception& error) {
    s.jump_unsmoothed_Ns = std::numeric_limits<double>::quiet_NaN();
    s.relative_change = std::numeric_limits<double>::quiet_NaN();
    s.unsmoothed_error = error.what();
  }
  const auto scatters = [&](const std::shared_ptr<const ProfileCurve>& curve) {
    if (!smoothed(curve)) return false;
    const ProfileSmoothing& smoothing = curve->smoothing();
    return smoothing.point_scatter_m && *smoothing.point_scatter_m > smoothing.tolerance_m;
  };
  s.scatter_beyond_tolerance = scatters(joint.measured_head) || scatters(wheel.measured_tread);
  s.sensitive = !(std::abs(s.relative_change) <= 0.01) || s.scatter_beyond_tolerance;
  return s;
}

}  // namespace railjoint
