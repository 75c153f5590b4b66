#include "scenes/sweeps/sample_design.h"

#include <numeric>
#include <random>

namespace railjoint {

namespace {

// The top 53 bits as a double in [0, 1): every value equally likely.
double unit_double(std::mt19937_64& engine) { return static_cast<double>(engine() >> 11) * 0x1.0p-53; }

// Uniform in [0, bound) by rejection (no modulo bias).
std::uint64_t below(std::mt19937_64& engine, std::uint64_t bound) {
  const std::uint64_t limit = std::numeric_limits<std::uint64_t>::max() - std::numeric_limits<std::uint64_t>::max() % bound;
  std::uint64_t x = engine();
  while (x >= limit) x = engine();
  return x % bound;
}

}  // namespace

std::vector<double> unit_sample(std::uint64_t count, std::size_t dimensions, std::uint64_t seed, SampleMethod method) {
  std::mt19937_64 engine(seed);
  std::vector<double> points(count * dimensions);
  if (method == SampleMethod::random) {
    for (double& x : points) x = unit_double(engine);
    return points;
  }
  // Latin hypercube: per dimension a random permutation of the strata
  // (Fisher-Yates), and a random place inside each stratum.
  std::vector<std::uint64_t> strata(count);
  for (std::size_t d = 0; d < dimensions; ++d) {
    std::iota(strata.begin(), strata.end(), std::uint64_t{0});
    for (std::uint64_t i = count; i > 1; --i) std::swap(strata[i - 1], strata[below(engine, i)]);
    for (std::uint64_t i = 0; i < count; ++i) {
      points[i * dimensions + d] = (static_cast<double>(strata[i]) + unit_double(engine)) / static_cast<double>(count);
    }
  }
  return points;
}

}  // namespace railjoint
