#pragma once
// What can go wrong in one simulated crossing, measured from its result and
// recorded trajectory against the kinematic model: NaN/Inf, a wheel that
// sank through the rail it should have climbed (tunnelling), a crossing with
// no detected impact, and drift of the vertical and horizontal velocity over
// the approach (the wheel starts on the kinematic path with the kinematic
// velocity, so any deviation before the impact is numerical). Pure function
// of the SimulationResult: no Bullet.

#include <string>

#include "models/parameters.h"
#include "sim/simulate_crossing.h"

namespace railjoint {

struct CrossingDiagnostics {
  /// (simulated - exact) / exact against result.prediction().impulse.exact_Ns
  /// (the governing slice as simulated); NaN when no impact was found.
  double relative_error = 0.0;
  bool non_finite = false;      ///< NaN/Inf in the result or any recorded sample
  std::string non_finite_where; ///< first place found, e.g. "sample 12 velocity"

  /// Largest depth of the wheel centre below the kinematic path after the
  /// predicted impact point [m] (0 if it never went below). The kinematic
  /// path is the lowest centre height at which the wheel does not cut the
  /// rails; a simulated wheel rests by the slop below it by design.
  double max_sink_m = 0.0;
  bool tunnelled = false;  ///< max_sink_m above kTunnelDepth_m
  /// The wheel centre passed the predicted impact point and no impact was detected.
  bool passed_without_impact = false;

  /// Largest |zdot - v dz/dx (kinematic path)| over the approach (centre at
  /// least kApproachGuard_m before the predicted impact point) [m/s].
  double approach_zdot_deviation_m_per_s = 0.0;
  /// The same over the exact jump in vertical velocity |zdot+ - zdot-|: the
  /// size of the error it puts into the measured jump [-].
  double approach_zdot_drift = 0.0;
  /// How far before the predicted impact point that largest deviation was [m].
  double approach_zdot_worst_before_impact_m = 0.0;
  /// Largest |xdot - v| / v over the approach [-].
  double approach_speed_drift = 0.0;
  int approach_samples = 0;  ///< samples the drifts were taken over
};

/// A centre this far below the kinematic path has gone into the rail, not
/// merely rested on it: 25 times the default slop (4 um), a tenth of the
/// smallest mismatch at the cut of the base scenes (~0.4 mm at y_w = 15 mm).
inline constexpr double kTunnelDepth_m = 1e-4;
/// The approach ends this far before the predicted impact point [m]: the
/// impact is placed to within one fine step of travel (0.05 mm at 50 m/s).
inline constexpr double kApproachGuard_m = 2e-4;

/// `joint` is the joint as simulated; the wheel is result.model->simulated_wheel.
CrossingDiagnostics diagnose_crossing(const JointParams& joint, const SimulationResult& result);

}  // namespace railjoint
