#include "sim/flight_hint.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "sim/crossing_model.h"
#include "sim/simulation_result.h"

namespace railjoint {

namespace {

// Below half of critical, an impact on the contact spring rebounds at more
// than e = exp(-pi 0.5 / sqrt(1 - 0.25)) = 0.16 of its speed (a linear
// spring-damper's restitution): enough for the bounces to outlast any run-out.
constexpr double kUnderdampedFraction = 0.5;

// The estimate is ballistic over a path taken as flat: some margin.
constexpr double kRunOutMargin = 1.25;

}  // namespace

double ballistic_landing_time_s(double clearance_m, double zdot_m_per_s, double downward_acceleration_m_per_s2) {
  const double a = downward_acceleration_m_per_s2;
  return (zdot_m_per_s + std::sqrt(zdot_m_per_s * zdot_m_per_s + 2.0 * a * std::max(0.0, clearance_m))) / a;
}

std::string ended_in_flight_hint(const SimulationResult& result) {
  const CrossingModel& model = *result.model;
  const SimSettings& settings = model.settings;
  std::ostringstream hint;
  hint.precision(3);
  if (const LinearContactSettings* spring = settings.inertial() ? settings.inertial()->linear_contact() : nullptr) {
    const double critical = critical_contact_damping_N_s_per_m(spring->stiffness_N_per_m, model.wheel.mass_kg);
    if (spring->damping_N_s_per_m < kUnderdampedFraction * critical) {
      hint << "the contact is underdamped (contact.damping = " << spring->damping_N_s_per_m
           << " N s/m, critical 2 sqrt(k M) = " << critical
           << " N s/m): it gives the impact's energy back and the wheel bounces on; leave contact.damping out for "
              "the critical default, or ";
    }
  }
  const WheelSample& last = result.trajectory.samples.back();
  const double clearance_m = last.centre_m.z() - model.reference_height_m(last.centre_m.x());
  const double landing_s = ballistic_landing_time_s(clearance_m, last.velocity_m_per_s.z(),
                                                    result.inertial()->static_load_N / model.wheel.mass_kg);
  const double run_out_s = std::ceil(kRunOutMargin * (model.run_out_time_s + landing_s) * 1e3) / 1e3;
  SimSettings longer = settings;
  longer.run_out_time_s = run_out_s;
  const double length_m = std::ceil(10.0 * rail_length_needed_m(model.joint, model.wheel, longer)) / 10.0;
  hint << "run it until the landing (about " << landing_s * 1e3 << " ms after the run's end, ballistic): --set "
       << "sim.run_out_time=" << run_out_s << " (joint.length follows it when not given; else at least "
       << length_m << " m)";
  return hint.str();
}

}  // namespace railjoint
