#pragma once
// The non-dominated points of an error-against-cost cloud: the settings for
// which no other setting is both at least as accurate and at least as fast
// (and strictly better in one). Used by the convergence study to name the
// settings worth using.

#include <cstddef>
#include <optional>
#include <vector>

namespace railjoint {

struct ParetoPoint {
  double error = 0.0;  ///< |relative error| [-]; NaN = no result (never on the front)
  double cost = 0.0;   ///< e.g. median wall time [s]
};

/// Errors at or below this are taken as equal (all "exact"): below it the
/// differences are where the step grid happens to put the located impact
/// inside the solving gap (0 to 6e-9 of the default scene's jump at the
/// default 1e-11 m, sim_settings.h), not resolution. The analytic forms
/// themselves differ by ~1e-4 (models/DESIGN.md "Three forms of every analytic impulse").
inline constexpr double kErrorResolution = 1e-8;

/// Errors within this relative difference are taken as equal: settings that
/// give the same jump to the fifth digit (4 and 10 solver iterations) differ
/// in run time only.
inline constexpr double kErrorTie = 0.01;

/// Indices of the non-dominated points, by increasing cost. Points with a
/// NaN error or cost are skipped; errors below kErrorResolution count as
/// kErrorResolution, errors within kErrorTie of each other as equal.
std::vector<std::size_t> pareto_front(const std::vector<ParetoPoint>& points);

/// How much a setting on or off the front leaves on the table: among the
/// points at least as good in both error and cost (errors resolved as
/// above), the largest gain one of them offers in either, as a factor
/// (error / error_other or cost / cost_other).
struct Domination {
  double factor = 1.0;  ///< 1 = nothing dominates it; 1.1 = within 10 %; NaN = the point has no result
  std::optional<std::size_t> by;  ///< the point that offers that gain
};
Domination domination(const std::vector<ParetoPoint>& points, std::size_t index);

}  // namespace railjoint
