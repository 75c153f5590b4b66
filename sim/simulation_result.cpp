#include "sim/simulation_result.h"

namespace railjoint {

std::optional<double> SimulationResult::liftoff_time_s() const {
  if (const InertialOutcome* out = inertial()) {
    if (out->flights.empty()) return std::nullopt;
    return out->flights.front().liftoff_time_s;
  }
  return std::get<KinematicOutcome>(outcome).liftoff_time_s;
}

}  // namespace railjoint
