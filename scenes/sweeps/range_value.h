#pragma once
// A point of a sweep's even or log range, at fraction t of the way from
// `from` to `to`, finite for any finite ends: to - from and to / from
// overflow for ends near the largest double (-1e308..1e308, 1e-200..1e200),
// so those ranges are interpolated as weighted ends, or in logarithms.

#include <cmath>
#include <cstdint>

namespace railjoint {

/// Value i of an even range of n values (n >= 2). (to - from) i / (n - 1)
/// rather than (to - from) t where it is finite: 0.019 * 5 / 38 is 0.0025,
/// 0.019 * (5 / 38) is not.
inline double even_range_value(double from, double to, std::uint64_t i, std::uint64_t n) {
  const double value = from + (to - from) * static_cast<double>(i) / static_cast<double>(n - 1);
  if (std::isfinite(value)) return value;
  const double t = static_cast<double>(i) / static_cast<double>(n - 1);
  return from * (1.0 - t) + to * t;
}

/// The even range's value at t in [0, 1] (a sampled point).
inline double even_range_at(double from, double to, double t) {
  const double value = from + (to - from) * t;
  return std::isfinite(value) ? value : from * (1.0 - t) + to * t;
}

/// A log range's value at t in [0, 1]; from, to > 0.
inline double log_range_at(double from, double to, double t) {
  const double value = from * std::pow(to / from, t);
  if (std::isfinite(value) && value > 0.0) return value;
  return std::exp(std::log(from) * (1.0 - t) + std::log(to) * t);
}

/// Value i of a grid range of n values (n >= 1): the ends exact, `from` and
/// `to` themselves, not from + (to - from) * 1 rounded.
inline double range_value(double from, double to, std::uint64_t i, std::uint64_t n, bool log) {
  if (i == 0) return from;
  if (i + 1 == n) return to;
  return log ? log_range_at(from, to, static_cast<double>(i) / static_cast<double>(n - 1))
             : even_range_value(from, to, i, n);
}

}  // namespace railjoint
