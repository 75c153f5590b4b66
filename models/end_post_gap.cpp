#include "models/end_post_gap.h"

#include <cmath>

namespace railjoint {

double longitudinal_gap_m(const EndPostGap& gap) { return gap.gap_m / std::sin(gap.theta_rad); }

Eigen::Vector2d cut_normal(const EndPostGap& gap) { return {std::sin(gap.theta_rad), -std::cos(gap.theta_rad)}; }

std::array<Eigen::Vector2d, 4> gap_parallelogram_m(const EndPostGap& gap, double width_m) {
  const double g_long = longitudinal_gap_m(gap);
  // cos/sin rather than 1/tan: exactly 0 offset is not needed, but tan(pi/2) is huge, not infinite.
  const double shift = width_m * std::cos(gap.theta_rad) / std::sin(gap.theta_rad);
  return {Eigen::Vector2d(0.0, 0.0), Eigen::Vector2d(g_long, 0.0), Eigen::Vector2d(shift + g_long, width_m),
          Eigen::Vector2d(shift, width_m)};
}

}  // namespace railjoint
