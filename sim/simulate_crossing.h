#pragma once
// The single entry point of the simulation: build the Bullet scene of one
// wheel crossing one joint, run it, and measure the vertical momentum jump
// against the analytic prediction. Used by `railjoint simulate`, `validate`,
// `render`, the studies, the tests and the benchmarks. No Bullet in this
// header.

#include <optional>

#include <Eigen/Core>

#include "models/impact_prediction.h"
#include "models/parameters.h"
#include "sim/sim_settings.h"
#include "sim/trajectory.h"

namespace railjoint {

struct SimulationResult {
  /// The prediction the simulation is compared with: the governing slice of
  /// the wheel as simulated (a thin disc is simulated as a cylinder of width
  /// 2 * disc_half_width, whose inner face strikes first).
  ImpactPrediction prediction;
  /// For a thin-disc scene (wheel.width = 0): the width-0 prediction, the
  /// value the simulation approaches as disc_half_width -> 0.
  std::optional<ImpactPrediction> thin_disc_prediction;
  WheelParams simulated_wheel;  ///< the wheel as simulated (width replaced for a disc)
  double preload_N = 0.0;       ///< the downward force used (resolved when automatic) [N]

  bool impact_found = false;
  double impulse_Ns = 0.0;                ///< M (zdot+ - zdot-) of the impact (both sides extrapolated) [N s]
  double impulse_from_contacts_Ns = 0.0;  ///< same from the summed vertical contact impulses [N s]
  double impact_time_s = 0.0;
  double impact_x_m = 0.0;                ///< wheel centre x at the impact [m]
  double zdot_before_m_per_s = 0.0;
  double zdot_after_m_per_s = 0.0;
  Eigen::Vector3d contact_struck_m = Eigen::Vector3d::Zero();  ///< vs prediction.contact_A_m
  Eigen::Vector3d contact_left_m = Eigen::Vector3d::Zero();    ///< vs prediction.contact_B_m (NaN on landing)

  /// Largest overlap between wheel and rail over the run [m]; resting
  /// contacts overlap by the slop by design.
  double max_penetration_m = 0.0;
  bool liftoff = false;          ///< the wheel left the rails after the impact
  double liftoff_time_s = -1.0;  ///< when (negative if it did not)
  bool second_impact = false;    ///< it landed again within the run
  double second_impact_time_s = -1.0;
  double second_impulse_Ns = 0.0;

  double wall_seconds = 0.0;  ///< building the world and stepping, one core [s]
  int steps = 0;
  int refined_steps = 0;
  Trajectory trajectory;  ///< every step, with contacts; trajectory.impacts lists all detected impacts
};

/// Axle load of a bogie wheel, about 14 times the wheel's weight [N].
inline constexpr double kDefaultPreload_N = 1e5;

/// The preload used when SimSettings::preload_N is empty: 2 M v^2 / R when
/// the jump happens on landing (the kinematic wheel first pivots about the
/// corner it rolls off, which needs M v^2 / R), else kDefaultPreload_N.
double automatic_preload_N(const ImpactPrediction& prediction, const WheelParams& wheel);

/// Throws ParameterError for parameters outside the model (key "joint.*",
/// "wheel.*") or settings that cannot work together (key "sim.*").
SimulationResult simulate_crossing(const JointParams& joint, const WheelParams& wheel, const SimSettings& settings);

/// Checks the settings and the combinations the [sim] range checks cannot
/// see (margin below the disc half width, run inside the rail ends, ...);
/// throws ParameterError("sim.<key>", ...).
void check_sim_settings(const SimSettings& settings, const JointParams& joint, const WheelParams& wheel);

}  // namespace railjoint
