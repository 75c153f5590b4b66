#include "models/time_history.h"

#include <cassert>
#include <cmath>

#include "models/impact_prediction.h"
#include "models/kinematic_trajectory.h"
#include "support/run_interrupt.h"

namespace railjoint {

HistoryReach time_history_reach(const JointParams& joint, const WheelParams& wheel, const ImpactPrediction& p) {
  const double lead_m = joint.kind == JointKind::step ? 0.0 : wheel.radius_m * std::sin(joint.beta_rad / 2.0);
  const double half_length_m = joint.length_m / 2.0;
  return {p.impact_wheel_x_m + half_length_m - lead_m, half_length_m - lead_m - p.impact_wheel_x_m};
}

TimeHistory impact_time_history(const JointParams& joint, const WheelParams& wheel, double before_s, double after_s,
                                int samples) {
  return impact_time_history(joint, wheel, predict_impact(joint, wheel), before_s, after_s, samples);
}

TimeHistory impact_time_history(const JointParams& joint, const WheelParams& wheel, const ImpactPrediction& p,
                                double before_s, double after_s, int samples) {
  assert(samples >= 2 && before_s >= 0.0 && after_s >= 0.0);
  const double v = wheel.speed_m_per_s;
  // The thesis's linearised vertical velocities on either side (sin forms).
  double zdot_in = 0.0;
  double zdot_out = 0.0;
  const double sin_half_beta = std::sin(joint.beta_rad / 2.0);
  switch (p.scenario) {
    case ImpactScenario::one:
      zdot_in = -sin_half_beta * v;
      zdot_out = sin_half_beta * v;
      break;
    case ImpactScenario::two:
      zdot_in = (p.on_landing ? -std::sin(p.alpha_thesis_rad) : -sin_half_beta) * v;
      zdot_out = (p.on_landing ? sin_half_beta : std::sin(p.alpha_thesis_rad)) * v;
      break;
    case ImpactScenario::step:
      zdot_in = p.on_landing ? -p.impulse.thesis_Ns / wheel.mass_kg : 0.0;
      zdot_out = p.on_landing ? 0.0 : p.impulse.thesis_Ns / wheel.mass_kg;
      break;
  }

  // The general model has no thesis form, the step's may have no real value:
  // no linearised path then, rather than one built on a NaN slope.
  const bool linear = std::isfinite(p.impulse.thesis_Ns);

  TimeHistory h;
  const KinematicPath path(joint, wheel);
  const double dt = (before_s + after_s) / (samples - 1);
  for (std::vector<double>* column : {&h.time_s, &h.z_exact_m, &h.zdot_exact_m_per_s, &h.momentum_exact_Ns,
                                      &h.impulse_exact_Ns}) {
    column->reserve(static_cast<std::size_t>(samples));
  }
  if (linear) {
    h.z_linear_m.reserve(static_cast<std::size_t>(samples));
    h.zdot_linear_m_per_s.reserve(static_cast<std::size_t>(samples));
  }
  for (int i = 0; i < samples; ++i) {
    // Python's time_history(samples=10_000_000) runs for seconds: Ctrl-C ends it (support/run_interrupt.h).
    poll_run_interrupt(i + 1);
    const double t = -before_s + i * dt;
    const double x = p.impact_wheel_x_m + v * t;
    const int side = t > 0.0 ? +1 : -1;
    h.time_s.push_back(t);
    h.z_exact_m.push_back(path.centre_height_m(x) - p.impact_wheel_z_m);
    h.zdot_exact_m_per_s.push_back(v * path.centre_slope(x, side));
    if (linear) {
      h.z_linear_m.push_back((t > 0.0 ? zdot_out : zdot_in) * t);
      h.zdot_linear_m_per_s.push_back(t > 0.0 ? zdot_out : zdot_in);
    }
    h.momentum_exact_Ns.push_back(wheel.mass_kg * h.zdot_exact_m_per_s.back());
    h.impulse_exact_Ns.push_back(i == 0 ? 0.0 : h.momentum_exact_Ns[i] - h.momentum_exact_Ns[i - 1]);
  }
  return h;
}

}  // namespace railjoint
