#pragma once
// The step-size rule both crossings share for contacts about to close: a
// closing gap below sim.refine_distance asks for the fine step; above it the
// next step is a quarter of the time the gap needs to close (never below the
// fine step), so the approach to an impact takes a handful of steps.

#include <algorithm>
#include <vector>

#include "sim/sim_settings.h"
#include "sim/trajectory.h"

namespace railjoint {

/// A contact closes when its gap shrinks faster than this fraction of the
/// horizontal speed: resting contacts' normals are off by ~1e-4, times v;
/// impacts close at v (tan alpha + tan(beta/2)) >= 0.015 v.
inline constexpr double kClosingSpeedFraction = 2e-3;

struct ClosingGapStep {
  bool refine = false;    ///< a closing gap is (nearly) shut: hold the fine step
  double next_dt_s = 0;   ///< otherwise the longest safe next step [s]
};

/// contacts: as recorded after a step of dt_s [s]; speed: horizontal wheel speed [m/s].
inline ClosingGapStep closing_gap_step(const std::vector<ContactSample>& contacts, const SimSettings& settings,
                                       double speed_m_per_s, double dt_s) {
  ClosingGapStep out;
  out.next_dt_s = settings.time_step_s;
  // Closed contacts still closing are impacts under way: they count as gap <= 0.
  const double closing_speed_m_per_s = kClosingSpeedFraction * speed_m_per_s;
  for (const ContactSample& c : contacts) {
    if (c.normal_velocity_m_per_s >= -closing_speed_m_per_s) continue;
    // The recorded gap is from the start of the step (Bullet detects, then
    // integrates); the solver takes a contact from the processing threshold on.
    const double gap_now_m = c.distance_m - settings.contact_processing_threshold_m + c.normal_velocity_m_per_s * dt_s;
    if (gap_now_m < settings.refine_distance_m) {
      out.refine = true;
    } else {
      out.next_dt_s =
          std::min(out.next_dt_s, std::max(settings.refined_time_step_s, 0.25 * gap_now_m / -c.normal_velocity_m_per_s));
    }
  }
  return out;
}

}  // namespace railjoint
