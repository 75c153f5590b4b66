#include "sim/time_origin.h"

#include <cassert>

namespace railjoint {

double passage_time_s(const std::vector<WheelSample>& samples, double x_m) {
  assert(!samples.empty());
  const auto carried = [&](const WheelSample& s) { return s.time_s + (x_m - s.centre_m.x()) / s.velocity_m_per_s.x(); };
  if (x_m <= samples.front().centre_m.x()) return carried(samples.front());
  for (std::size_t k = 1; k < samples.size(); ++k) {
    const WheelSample& a = samples[k - 1];
    const WheelSample& b = samples[k];
    if (b.centre_m.x() < x_m) continue;
    const double span_m = b.centre_m.x() - a.centre_m.x();
    const double share = span_m > 0.0 ? (x_m - a.centre_m.x()) / span_m : 1.0;
    return a.time_s + share * (b.time_s - a.time_s);
  }
  return carried(samples.back());
}

double simulation_time_origin_s(const SimulationResult& result) {
  const ImpactPrediction& scene_wheel = result.scene_wheel_prediction();
  return passage_time_s(result.trajectory.samples, scene_wheel.impact_wheel_x_m);
}

Trajectory on_output_clock(Trajectory trajectory, double origin_s) {
  for (WheelSample& s : trajectory.samples) {
    s.time_s -= origin_s;
    s.velocity_time_s -= origin_s;
  }
  for (ImpactEvent& e : trajectory.impacts) e.time_s -= origin_s;
  return trajectory;
}

}  // namespace railjoint
