#pragma once
// Range checks of [sim] keys, shared by the kinematic and the inertial
// crossing: one ParameterError naming "sim.<key>" and the allowed range.

#include <sstream>
#include <string>

#include "models/parameter_error.h"
#include "models/parameters.h"
#include "sim/sim_settings.h"

namespace railjoint {

/// A number as the user would type it (shortest round-trip is not needed here).
inline std::string setting_number(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

inline void require_setting(bool ok, const std::string& key, const std::string& message) {
  if (!ok) throw ParameterError("sim." + key, message);
}

/// The wheel as simulated: a thin disc (width 0) becomes a cylinder of width
/// 2 sim.disc_half_width (Bullet has no zero-width shape).
inline WheelParams wheel_as_simulated(const WheelParams& wheel, const SimSettings& settings) {
  WheelParams simulated = wheel;
  if (simulated.width_m == 0.0) simulated.width_m = 2.0 * settings.disc_half_width_m;
  return simulated;
}

}  // namespace railjoint
