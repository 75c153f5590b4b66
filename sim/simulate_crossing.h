#pragma once
// The single entry point of the simulation: build the model of one wheel
// crossing one joint (crossing_model.h), run the one stepping loop
// (crossing_run.h) and measure the vertical momentum jump against the
// analytic prediction (crossing_analysis.h). Used by `railjoint simulate`,
// `validate`, `render`, the studies, the tests and the benchmarks. No Bullet
// in this header.

#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "models/impact_prediction.h"
#include "models/parameters.h"
#include "sim/contact_phases.h"
#include "sim/crossing_model.h"
#include "sim/force_outcome.h"
#include "sim/setting_checks.h"
#include "sim/sim_settings.h"
#include "sim/trajectory.h"

namespace railjoint {

/// What an inertial-mode run adds (sim_settings.h SimMode::inertial): every
/// contact phase, flight and impact, and the comparisons with the lift-off
/// model (models/liftoff.h) and, with a compliant contact, with the P1
/// estimate (sim/impact_force_estimate.h).
struct InertialOutcome {
  double wheel_load_N = 0.0;    ///< F, the static wheel load besides the weight [N]
  double static_load_N = 0.0;   ///< W = F + M g, the static contact force [N]
  HorizontalMotion horizontal = HorizontalMotion::held;
  double carrier_mass_kg = 0.0;       ///< free horizontal motion: mass moving with the wheel besides it [kg]
  bool spinning = false;              ///< friction > 0: the wheel's spin was free
  double flat_approach_m = 0.0;

  std::vector<ContactPhase> phases;   ///< contact and flight intervals covering the run
  std::vector<Flight> flights;
  bool ended_in_flight = false;       ///< the run ended before the wheel landed (lengthen run_out_time, joint.length)
  /// Index into trajectory.impacts of the impact at the joint: the largest
  /// one within 10 mm of the predicted two-point contact, else the first one
  /// after that (the wheel flew over it); -1 if none.
  int joint_impact_index = -1;
  /// Sum of all momentum jumps of the run (rigid contact), or of all force
  /// pulses' impulses (compliant) [N s].
  double total_impulse_Ns = 0.0;

  /// Largest |z - z_kinematic(x)| over the run and where; z_kinematic is
  /// kinematic_centre_height_m (and the pivot over the entry kink and the
  /// flat before it when there is a flat approach) [m].
  double max_deviation_m = 0.0;
  double max_deviation_x_m = 0.0;
  double max_rise_m = 0.0;   ///< highest above the kinematic path [m]
  double max_sink_m = 0.0;   ///< deepest below it (compliant contact) [m]
  /// No flight and max deviation within 20 um (plus the contact's largest
  /// compression when compliant): the wheel stayed glued.
  bool followed_kinematic_path = false;

  /// Lift-off model, horizontal speed held: the angle of the radius to the
  /// corner the wheel pivots about at the joint (scenario 2 and step up:
  /// right after the impact; step down: at the landing) and the speed above
  /// which the static load cannot keep it on that arc. NaN for scenario 1
  /// (no convex corner).
  double pivot_angle_rad = std::numeric_limits<double>::quiet_NaN();
  double pivot_liftoff_speed_m_per_s = std::numeric_limits<double>::quiet_NaN();
  /// Same for the entry kink of the dip (flat approach only; angle beta/2).
  double entry_kink_liftoff_speed_m_per_s = std::numeric_limits<double>::quiet_NaN();
  bool liftoff_predicted = false;  ///< v above one of those speeds

  /// Horizontal velocity either side of the joint impact (fitted, extrapolated) and
  /// the horizontal contact impulse over it [m/s, N s].
  double xdot_before_m_per_s = 0.0;
  double xdot_after_m_per_s = 0.0;
  double joint_horizontal_impulse_Ns = 0.0;

  bool compliant = false;
  double contact_stiffness_N_per_m = 0.0;
  double contact_damping_N_s_per_m = 0.0;
  double peak_force_N = 0.0;         ///< largest summed vertical contact force of the run [N]
  double peak_force_time_s = 0.0;
  double peak_force_x_m = 0.0;
  /// P0 + dv sqrt(k M) with dv the exact kinematic jump / M: Jenkins's P1
  /// for a rigid track (impact_force_estimate.h); compliant runs only [N].
  double rigid_track_p1_N = 0.0;
  /// The same with Jenkins's own dv = 2 alpha v = beta v (the dip angle). The
  /// two agree in scenario 1; which one a scenario-2 peak follows depends on
  /// how long the wheel pivots about the edge (README, inertia section) [N].
  double rigid_track_p1_beta_v_N = 0.0;

  /// Force runs (Hertz contact, maybe an elastic track): P1, P2 and the
  /// track's history. The compliant fields above then hold K_H for the stiffness.
  std::optional<ForceOutcome> forces;
};

/// Whether a run can vouch for its jump (a wrong number must never
/// look right). "suspect" runs exit 1 from the CLI.
struct SimVerdict {
  bool ok = false;
  std::string reason;  ///< empty when ok; otherwise every check that failed, "; "-separated
};

struct SimulationResult {
  /// What was simulated: joint, wheels, settings, rails, start (shared, so
  /// copies of a result and the renderer read the same rails).
  std::shared_ptr<const CrossingModel> model;
  /// The prediction the simulation is compared with: the governing slice of
  /// the wheel as simulated (a thin disc is simulated as a cylinder of width
  /// 2 * disc_half_width, whose inner face strikes first).
  ImpactPrediction prediction;
  /// For a thin-disc scene (wheel.width = 0): the width-0 prediction, the
  /// value the simulation approaches as disc_half_width -> 0.
  std::optional<ImpactPrediction> thin_disc_prediction;
  WheelParams simulated_wheel;  ///< the wheel as simulated (width replaced for a disc)
  double preload_N = 0.0;       ///< the downward force used besides gravity (resolved when automatic; inertial mode: the wheel load) [N]

  bool impact_found = false;
  double impulse_Ns = 0.0;                ///< M (zdot+ - zdot-) of the impact (both sides extrapolated) [N s]
  double impulse_from_contacts_Ns = 0.0;  ///< same from the summed vertical contact impulses [N s]
  double impact_time_s = 0.0;
  double impact_x_m = 0.0;                ///< wheel centre x at the impact [m]
  double zdot_before_m_per_s = 0.0;
  double zdot_after_m_per_s = 0.0;
  /// Contact points; NaN when not measured (no impact, a landing leaves no
  /// point, a compliant force pulse has no single instant to read them at).
  Eigen::Vector3d contact_struck_m = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());  ///< vs prediction.contact_A_m
  Eigen::Vector3d contact_left_m = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());    ///< vs prediction.contact_B_m

  /// Largest overlap between wheel and rail over the run [m]; resting
  /// contacts overlap by the slop by design.
  double max_penetration_m = 0.0;
  bool liftoff = false;          ///< the wheel left the rails after the impact
  double liftoff_time_s = -1.0;  ///< when (negative if it did not)
  bool second_impact = false;    ///< it landed again within the run
  double second_impact_time_s = -1.0;
  double second_impulse_Ns = 0.0;

  SimVerdict verdict;
  double wall_seconds = 0.0;  ///< building the world and stepping, one core [s]
  int steps = 0;
  int refined_steps = 0;
  Trajectory trajectory;  ///< every step, with contacts; trajectory.impacts lists all detected impacts

  /// Inertial mode only. There the fields above describe the impact at the
  /// joint (inertial->joint_impact_index); `liftoff` is any flight of the run
  /// and `second_impact` the next impact after the joint's.
  std::optional<InertialOutcome> inertial;
};

/// Throws InputError for parameters outside the model (key "joint.*",
/// "wheel.*") or settings that cannot work together (key "sim.*").
SimulationResult simulate_crossing(const JointParams& joint, const WheelParams& wheel, const SimSettings& settings);

}  // namespace railjoint
