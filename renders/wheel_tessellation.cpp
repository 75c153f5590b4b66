#include "renders/wheel_tessellation.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace railjoint {

int wheel_render_segments(const RenderSettings& settings, double wheel_radius_m, double max_gap_px) {
  if (!(wheel_radius_m > 0.0) || !(max_gap_px > 0.0)) {
    throw std::invalid_argument("render: wheel radius and allowed gap must be positive, got R = " +
                                std::to_string(wheel_radius_m) + " m, gap = " + std::to_string(max_gap_px) + " px");
  }
  const double width_m = settings.view_width_m.value_or(kDefaultContactViewWidth_m);
  const double px_per_m = static_cast<double>(settings.width_px) / width_m;
  // k s R (1 - cos(pi / N)) <= gap: the circle is drawn k s R pixels tall at the contact.
  return polygon_sides_for_radius_px(settings.exaggeration * px_per_m * wheel_radius_m, max_gap_px);
}

int polygon_sides_for_radius_px(double radius_px, double max_gap_px) {
  if (!(radius_px > 0.0) || !(max_gap_px > 0.0)) {
    throw std::invalid_argument("render: drawn radius and allowed gap must be positive, got " +
                                std::to_string(radius_px) + " px, gap = " + std::to_string(max_gap_px) + " px");
  }
  // r (1 - cos(pi / N)) <= gap  <=>  N >= pi / acos(1 - gap / r).
  const double relative_gap = max_gap_px / radius_px;
  if (relative_gap >= 1.0) return kMinWheelRenderSegments;
  const double n = std::ceil(std::numbers::pi / std::acos(1.0 - relative_gap));
  return static_cast<int>(std::clamp(n, double{kMinWheelRenderSegments}, double{kMaxWheelRenderSegments}));
}

}  // namespace railjoint
