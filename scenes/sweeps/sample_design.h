#pragma once
// Points in the unit cube for a sampled sweep: plain random, or a Latin
// hypercube (each coordinate's n strata [k/n, (k+1)/n) hold one point each,
// so n points cover every range evenly however many dimensions there are).
// Reproducible on any machine and compiler: the generator is std::mt19937_64,
// whose sequence the C++ standard fixes, and the conversions to doubles and
// to bounded integers are written here (std::uniform_*_distribution are
// implementation-defined).

#include <cstdint>
#include <vector>

#include "scenes/sweeps/sweep_file.h"

namespace railjoint {

/// count x dimensions coordinates in [0, 1), point-major: point i's
/// coordinate d is at [i * dimensions + d].
std::vector<double> unit_sample(std::uint64_t count, std::size_t dimensions, std::uint64_t seed, SampleMethod method);

}  // namespace railjoint
