#include "scenes/studies/pareto_front.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace railjoint {

namespace {

bool has_result(const ParetoPoint& p) { return std::isfinite(p.error) && std::isfinite(p.cost); }

double resolved(double error) { return std::max(error, kErrorResolution); }

// a dominates b: no worse in both, better in one (errors compared up to the tie).
bool dominates(const ParetoPoint& a, const ParetoPoint& b) {
  const double ea = resolved(a.error);
  const double eb = resolved(b.error);
  const bool error_no_worse = ea <= eb * (1.0 + kErrorTie);
  const bool error_better = ea * (1.0 + kErrorTie) < eb;
  return error_no_worse && a.cost <= b.cost && (error_better || a.cost < b.cost);
}

}  // namespace

std::vector<std::size_t> pareto_front(const std::vector<ParetoPoint>& points) {
  std::vector<std::size_t> front;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!has_result(points[i])) continue;
    bool dominated = false;
    for (std::size_t j = 0; j < points.size() && !dominated; ++j) {
      dominated = j != i && has_result(points[j]) && dominates(points[j], points[i]);
    }
    if (!dominated) front.push_back(i);
  }
  std::sort(front.begin(), front.end(), [&](std::size_t a, std::size_t b) { return points[a].cost < points[b].cost; });
  return front;
}

Domination domination(const std::vector<ParetoPoint>& points, std::size_t index) {
  const ParetoPoint& p = points.at(index);
  Domination d;
  if (!has_result(p)) {
    d.factor = std::numeric_limits<double>::quiet_NaN();
    return d;
  }
  for (std::size_t j = 0; j < points.size(); ++j) {
    if (j == index || !has_result(points[j]) || !dominates(points[j], p)) continue;
    // A zero cost dominates a positive one by an unbounded factor.
    const double gain = std::max(resolved(p.error) / resolved(points[j].error),
                                 points[j].cost > 0.0 ? p.cost / points[j].cost : std::numeric_limits<double>::infinity());
    if (gain > d.factor) {
      d.factor = gain;
      d.by = j;
    }
  }
  return d;
}

}  // namespace railjoint
