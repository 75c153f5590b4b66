#include "sim/hertz_law.h"

#include <algorithm>
#include <cmath>

namespace railjoint {

double hunt_crossley_restitution(double damping_factor) {
  if (!(damping_factor > 0.0)) return 1.0;
  const double alpha = damping_factor;
  // Scaled impact X'' = -X^(3/2) max(0, 1 + alpha X'), by RK4 with a step
  // below the damping's own rate alpha X^(3/2) and 1/600 of the undamped
  // contact's 2.94 long half period (RK4's error ~ h^4: 1e-10).
  const auto acceleration = [alpha](double x, double v) {
    return x > 0.0 ? -x * std::sqrt(x) * std::max(0.0, 1.0 + alpha * v) : 0.0;
  };
  double x = 0.0, v = 1.0;
  for (int step = 0; step < 10000000; ++step) {
    // The force has vanished during the rebound (1 + alpha X' -> 0, which X'
    // approaches exponentially once the damping dominates) and stays so: the
    // bodies part at X' = -1 / alpha.
    if (v < 0.0 && 1.0 + alpha * v <= 1e-12) return 1.0 / alpha;
    if (x < 0.0 && v < 0.0) return -v;
    const double h = std::min(5e-3, 0.05 / (alpha * std::max(x, 0.0) * std::sqrt(std::max(x, 0.0)) + 1e-12));
    const double k1x = v, k1v = acceleration(x, v);
    const double k2x = v + 0.5 * h * k1v, k2v = acceleration(x + 0.5 * h * k1x, v + 0.5 * h * k1v);
    const double k3x = v + 0.5 * h * k2v, k3v = acceleration(x + 0.5 * h * k2x, v + 0.5 * h * k2v);
    const double k4x = v + h * k3v, k4v = acceleration(x + h * k3x, v + h * k3v);
    x += h / 6.0 * (k1x + 2 * k2x + 2 * k3x + k4x);
    v += h / 6.0 * (k1v + 2 * k2v + 2 * k3v + k4v);
  }
  return -v;
}

double hunt_crossley_damping_factor(double restitution) {
  if (restitution >= 1.0) return 0.0;
  const double e = std::max(restitution, kSmallestRestitution);
  // Strong damping: the force vanishes during the rebound and e = 1 / alpha
  // exactly (from e ~ 0.1 down).
  if (std::abs(hunt_crossley_restitution(1.0 / e) / e - 1.0) < 1e-12) return 1.0 / e;
  // Otherwise e(alpha), falling from 1 at alpha = 0, by bisection in log alpha.
  double low = 1e-9, high = 2.0 / e;
  for (int i = 0; i < 80 && high / low > 1.0 + 1e-10; ++i) {
    const double mid = std::sqrt(low * high);
    (hunt_crossley_restitution(mid) > e ? low : high) = mid;
  }
  return std::sqrt(low * high);
}

}  // namespace railjoint
