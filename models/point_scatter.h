#pragma once
// How much a measured profile's points scatter about a smooth curve,
// estimated from the points alone. The smoothing (profile_curve.h) removes
// a scatter up to its tolerance; a scatter beyond it survives the
// smoothing, and then the smoothed and the unsmoothed jumps agree while
// both are wrong (a 300 mm crown rounded to 10 um every 0.05 mm: +12 %,
// the two within 0.1 %). This estimate is what tells the user so.

#include <optional>
#include <vector>

namespace railjoint {

/// The RMS scatter [m] of `value_m` about a smooth curve of `y_m`
/// (increasing): each point's residual from the least-squares cubic through
/// it and its two neighbours on each side, scaled to one point's scatter
/// by that fit's leverage, and the median of their magnitudes taken as
/// 0.6745 of the RMS (a normal scatter's median absolute value), so a few
/// points at a change of curvature (60E1's arc ends) do not count. A cubic
/// through five points leaves a smooth curve's own residual of order
/// h^4 f'''' (1e-11 m on 60E1's 13 mm arc sampled every 0.05 mm, 1e-7 m
/// every 0.5 mm). Empty for fewer than 5 points.
std::optional<double> point_scatter_m(const std::vector<double>& y_m, const std::vector<double>& value_m);

}  // namespace railjoint
