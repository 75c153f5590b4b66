#include "scenes/studies/crossing_diagnostics.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "models/jump_error.h"
#include "models/kinematic_trajectory.h"

namespace railjoint {

namespace {

bool finite(const Eigen::Vector3d& v) { return v.allFinite(); }

// First non-finite value in the result, or "" if all are finite.
std::string find_non_finite(const SimulationResult& r) {
  std::vector<std::pair<const char*, double>> scalars = {{"max_penetration", r.max_penetration_m}};
  if (r.impact) {
    const JointImpact& i = *r.impact;
    scalars.insert(scalars.end(), {{"impulse", i.impulse_Ns()},
                                   {"impulse_from_contacts", i.impulse_from_contacts_Ns()},
                                   {"impact_time", i.time_s()},
                                   {"impact_x", i.wheel_x_m()},
                                   {"zdot_before", i.zdot_before_m_per_s()},
                                   {"zdot_after", i.zdot_after_m_per_s()}});
  }
  if (r.second_impact) scalars.emplace_back("second_impulse", r.second_impact->impulse_Ns);
  for (const auto& [name, value] : scalars) {
    if (!std::isfinite(value)) return std::string("result ") + name;
  }
  if (r.impact && !finite(r.impact->struck_point_m())) return "result contact_struck";
  const auto& samples = r.trajectory.samples;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const WheelSample& s = samples[i];
    const std::string where = "sample " + std::to_string(i) + " ";
    if (!std::isfinite(s.time_s)) return where + "time";
    if (!finite(s.centre_m)) return where + "centre";
    if (!finite(s.velocity_m_per_s)) return where + "velocity";
    if (!std::isfinite(s.spin_angle_rad)) return where + "spin angle";
    for (const ContactSample& c : s.contacts) {
      if (!finite(c.point_on_rail_m) || !finite(c.normal) || !std::isfinite(c.distance_m) ||
          !std::isfinite(c.normal_impulse_Ns) || !std::isfinite(c.normal_velocity_m_per_s)) {
        return where + "contact";
      }
    }
  }
  for (std::size_t i = 0; i < r.trajectory.impacts.size(); ++i) {
    const ImpactEvent& e = r.trajectory.impacts[i];
    if (!std::isfinite(e.momentum_jump_Ns) || !std::isfinite(e.time_s) || !finite(e.contact_point_m)) {
      return "impact " + std::to_string(i);
    }
  }
  return "";
}

}  // namespace

CrossingDiagnostics diagnose_crossing(const JointParams& joint, const SimulationResult& r) {
  CrossingDiagnostics d;
  const ImpactPrediction& p = r.prediction();
  const WheelParams& wheel = r.model->simulated_wheel;
  const double v = wheel.speed_m_per_s;

  d.relative_error = r.impact_found() && p.impulse.exact_Ns != 0.0 ? relative_error(r.impulse_Ns(), p.impulse.exact_Ns)
                                                                   : std::numeric_limits<double>::quiet_NaN();
  d.non_finite_where = find_non_finite(r);
  d.non_finite = !d.non_finite_where.empty();

  const double exact_dzdot = std::abs(p.zdot_after_m_per_s - p.zdot_before_m_per_s);
  bool passed = false;
  const KinematicPath path(joint, wheel);
  for (const WheelSample& s : r.trajectory.samples) {
    if (!finite(s.centre_m) || !finite(s.velocity_m_per_s)) continue;  // reported above
    const double x = s.centre_m.x();
    if (x <= p.impact_wheel_x_m - kApproachGuard_m) {
      // Before the impact the kinematic centre path is a line (or, before a
      // landing, the pivot arc): its slope times v is the exact zdot, at the
      // x the velocity belongs to (WheelSample::velocity_time_s; on the pivot
      // a step behind: 0.18 % of the jump on the step-down side otherwise).
      const double x_of_velocity = x - v * (s.time_s - s.velocity_time_s);
      const double zdot_exact = v * path.centre_slope(x_of_velocity, -1);
      const double deviation = std::abs(s.velocity_m_per_s.z() - zdot_exact);
      if (deviation > d.approach_zdot_deviation_m_per_s) {
        d.approach_zdot_deviation_m_per_s = deviation;
        d.approach_zdot_worst_before_impact_m = p.impact_wheel_x_m - x;
      }
      d.approach_speed_drift = std::max(d.approach_speed_drift, std::abs(s.velocity_m_per_s.x() - v) / v);
      ++d.approach_samples;
    } else if (x > p.impact_wheel_x_m) {
      passed = true;
      // After the impact the wheel is on or above the path (lift-off); below
      // it only by resting overlap, or if it went into the rail.
      d.max_sink_m = std::max(d.max_sink_m, path.centre_height_m(x) - s.centre_m.z());
    }
  }
  d.approach_zdot_drift = exact_dzdot > 0.0 ? d.approach_zdot_deviation_m_per_s / exact_dzdot : 0.0;
  d.tunnelled = d.max_sink_m > kTunnelDepth_m;
  d.passed_without_impact = passed && !r.impact_found();
  return d;
}

}  // namespace railjoint
