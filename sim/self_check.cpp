#include "sim/self_check.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace railjoint {

SimVerdict kinematic_self_check(const SimulationResult& result, const SimSettings& settings, double speed_m_per_s,
                                double mass_kg, double approach_slope, const std::vector<double>& earlier_jumps_Ns,
                                const SelfCheckLimits& limits) {
  std::ostringstream reasons;
  const auto fail = [&reasons](const std::string& reason) {
    if (reasons.tellp() > 0) reasons << "; ";
    reasons << reason;
  };
  if (!result.impact_found) {
    fail("no impact found");
  } else {
    const double predicted_dv = std::abs(result.prediction.impulse.exact_Ns) / mass_kg;
    const double dx = result.impact_x_m - result.prediction.impact_wheel_x_m;
    if (!(std::abs(dx) <= limits.impact_x_m)) {
      std::ostringstream s;
      s << "impact at x = " << result.impact_x_m << " m, " << dx * 1e3 << " mm from the predicted one";
      fail(s.str());
    }
    const double drift = (result.zdot_before_m_per_s - speed_m_per_s * approach_slope) / predicted_dv;
    if (!(std::abs(drift) <= limits.approach_drift)) {
      std::ostringstream s;
      s << "approach velocity off the predicted path by " << drift << " of the jump's velocity change";
      fail(s.str());
    }
    const double disagreement = (result.impulse_from_contacts_Ns - result.impulse_Ns) / (mass_kg * predicted_dv);
    if (!(std::abs(disagreement) <= limits.estimator_disagreement)) {
      std::ostringstream s;
      s << "summed contact impulses differ from the velocity jump by " << disagreement << " of it";
      fail(s.str());
    }
  }
  if (!earlier_jumps_Ns.empty()) {
    std::ostringstream s;
    s << earlier_jumps_Ns.size() << " jump(s) before the predicted impact (first " << earlier_jumps_Ns.front()
      << " N s): the wheel left the kinematic path";
    fail(s.str());
  }
  const double overlap_beyond_slop = result.max_penetration_m - settings.slop_m;
  if (!(overlap_beyond_slop <= limits.penetration_m)) {
    std::ostringstream s;
    s << "wheel sank " << overlap_beyond_slop * 1e6 << " um into the rail beyond the slop";
    fail(s.str());
  }
  SimVerdict verdict;
  verdict.reason = reasons.str();
  verdict.ok = verdict.reason.empty();
  return verdict;
}

SimVerdict inertial_self_check(const SimulationResult& result, const SimSettings& settings,
                               const SelfCheckLimits& limits) {
  std::ostringstream reasons;
  const auto fail = [&reasons](const std::string& reason) {
    if (reasons.tellp() > 0) reasons << "; ";
    reasons << reason;
  };
  const InertialOutcome& out = *result.inertial;
  const bool finite = std::all_of(result.trajectory.samples.begin(), result.trajectory.samples.end(),
                                  [](const WheelSample& s) { return s.centre_m.allFinite() && s.velocity_m_per_s.allFinite(); });
  if (!finite) fail("the wheel's state became NaN or infinite");
  if (!result.impact_found) fail("no impact found at the joint");
  if (!out.compliant) {
    const double overlap_beyond_slop = result.max_penetration_m - settings.slop_m;
    if (!(overlap_beyond_slop <= limits.penetration_m)) {
      std::ostringstream s;
      s << "wheel sank " << overlap_beyond_slop * 1e6 << " um into the rail beyond the slop";
      fail(s.str());
    }
    if (result.impact_found) {
      const double disagreement =
          (result.impulse_from_contacts_Ns - result.impulse_Ns) / std::max(std::abs(result.impulse_Ns), 1e-300);
      if (!(std::abs(disagreement) <= limits.estimator_disagreement)) {
        std::ostringstream s;
        s << "summed contact impulses differ from the velocity jump by " << disagreement << " of it";
        fail(s.str());
      }
    }
  }
  // With sim.run_out_time given the user chose where the run ends; left
  // out, the run-out follows the predicted flight, and a wheel still in the
  // air at its end flew otherwise than predicted.
  if (out.ended_in_flight && !settings.run_out_time_s) {
    fail("the run ended with the wheel in flight although its run-out followed the predicted flight: the "
         "landing and the total impulse are missing (set sim.run_out_time [s], and joint.length)");
  }
  SimVerdict verdict;
  verdict.reason = reasons.str();
  verdict.ok = verdict.reason.empty();
  return verdict;
}

}  // namespace railjoint
