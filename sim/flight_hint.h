#pragma once
// What to change when an inertial run ends with the wheel in the air: the
// cause when the contact is underdamped (an undamped linear contact on a
// rigid track gives the impact's energy back, and the wheel bounces on
// whatever the run-out), and a run-out long enough for the landing,
// estimated from the run's last state. One text for the self-check's
// verdict and the report: following it must not end in the same hint.

#include <string>

namespace railjoint {

struct SimulationResult;

/// The hint for a run whose InertialOutcome::ended_in_flight is set.
std::string ended_in_flight_hint(const SimulationResult& result);

/// Time until a free wheel, `clearance_m` above its path and rising at
/// `zdot_m_per_s`, is back on it under `downward_acceleration_m_per_s2`
/// (weight and wheel load over the mass) [s]: the ballistic landing.
double ballistic_landing_time_s(double clearance_m, double zdot_m_per_s, double downward_acceleration_m_per_s2);

}  // namespace railjoint
