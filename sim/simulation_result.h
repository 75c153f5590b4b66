#pragma once
// What one simulated crossing measured (simulate_crossing.h runs it): the
// shared part every run has (the model it ran, the impact at the joint if
// one was found, the impact after it, the run's own verdict and record) and
// the part only its mode has (KinematicOutcome or InertialOutcome). The
// impact is a rigid contact's velocity jump or a compliant contact's force
// pulse, never both; a force run (Hertz contact, maybe an elastic track) adds
// its P1, P2 and track history (ForceOutcome) to the inertial outcome. What
// was simulated (joint, wheels, settings, the prediction, the load) is read
// from the model, never copied. No Bullet in this header.

#include <Eigen/Core>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "models/impact_prediction.h"
#include "sim/contact_phases.h"
#include "sim/crossing_model.h"
#include "sim/force_outcome.h"
#include "sim/momentum_jump.h"
#include "sim/trajectory.h"

namespace railjoint {

/// The impact at the joint as a rigid contact makes it: a velocity jump,
/// both sides fitted and extrapolated to the instant the struck gap closed
/// (momentum_jump.h).
using RigidJump = MomentumJump;

/// The impact at the joint as a compliant contact makes it: a force pulse,
/// which has no instant of impact. It extends either side of a rise above
/// 1.5 times the static load while the summed vertical contact force stays
/// above the static load W; its impulse, sum (F - W) dt over it, is exactly
/// the wheel's vertical momentum change over it.
struct CompliantPulse {
  /// The pulse as Trajectory::impacts lists it: momentum_jump_Ns its impulse
  /// sum (F - W) dt; time_s, wheel_x_m and contact_point_m (the contact
  /// carrying the largest vertical force) at its largest force, peak_force_N.
  ImpactEvent event;
  /// Velocities at the pulse's ends: the sample before its first step and its last sample [m/s].
  double zdot_before_m_per_s = 0.0;
  double zdot_after_m_per_s = 0.0;
  double xdot_before_m_per_s = 0.0;
  double xdot_after_m_per_s = 0.0;
};

/// The impact at the joint, rigid or compliant, with what both say read the same way.
class JointImpact {
 public:
  JointImpact(RigidJump jump) : impact_(std::move(jump)) {}         // NOLINT: either kind is an impact
  JointImpact(CompliantPulse pulse) : impact_(std::move(pulse)) {}  // NOLINT

  const RigidJump* rigid() const { return std::get_if<RigidJump>(&impact_); }
  const CompliantPulse* pulse() const { return std::get_if<CompliantPulse>(&impact_); }

  /// M (zdot+ - zdot-) of a jump, sum (F - W) dt of a pulse [N s].
  double impulse_Ns() const { return rigid() ? rigid()->jump_Ns : pulse()->event.momentum_jump_Ns; }
  /// The jump's instant, the pulse's peak [s].
  double time_s() const { return rigid() ? rigid()->time_s : pulse()->event.time_s; }
  double wheel_x_m() const { return rigid() ? rigid()->wheel_x_m : pulse()->event.wheel_x_m; }
  double zdot_before_m_per_s() const { return rigid() ? rigid()->zdot_before_m_per_s : pulse()->zdot_before_m_per_s; }
  double zdot_after_m_per_s() const { return rigid() ? rigid()->zdot_after_m_per_s : pulse()->zdot_after_m_per_s; }
  double xdot_before_m_per_s() const { return rigid() ? rigid()->xdot_before_m_per_s : pulse()->xdot_before_m_per_s; }
  double xdot_after_m_per_s() const { return rigid() ? rigid()->xdot_after_m_per_s : pulse()->xdot_after_m_per_s; }
  /// Where it struck: the jump's struck contact, the pulse's largest contact at its peak [m].
  const Eigen::Vector3d& struck_point_m() const {
    return rigid() ? rigid()->struck_point_m : pulse()->event.contact_point_m;
  }
  /// The jump from the summed contact impulses; a pulse's impulse is its summed contact force already [N s].
  double impulse_from_contacts_Ns() const { return rigid() ? rigid()->from_contacts_Ns : pulse()->event.momentum_jump_Ns; }
  /// The point the wheel leaves at a jump (NaN on a landing); a pulse has none (NaN) [m].
  Eigen::Vector3d left_point_m() const {
    return rigid() ? rigid()->left_point_m : Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  }

 private:
  std::variant<RigidJump, CompliantPulse> impact_;
};

/// The next impact after the joint's, within the run.
struct FollowingImpact {
  double time_s = 0.0;
  double impulse_Ns = 0.0;  ///< its jump, or its pulse's impulse [N s]
};

/// What a kinematic run (SimMode::kinematic) adds.
struct KinematicOutcome {
  /// When the wheel left the rails after the impact (it could not follow
  /// the pivot arc); empty when it stayed on them [s, run time].
  std::optional<double> liftoff_time_s;
};

/// The contact spring of a compliant inertial run (a linear contact, or
/// Hertz's linearised at the static load in a force run) and Jenkins's P1
/// for a rigid track with that spring (sim/impact_force_estimate.h).
struct CompliantContact {
  double stiffness_N_per_m = 0.0;
  double damping_N_s_per_m = 0.0;
  /// P0 + dv sqrt(k M) with dv the exact kinematic jump / M [N].
  double rigid_track_p1_N = 0.0;
  /// The same with Jenkins's own dv = 2 alpha v = beta v (the dip angle). The
  /// two agree in scenario 1; which one a scenario-2 peak follows depends on
  /// how long the wheel pivots about the edge (README, inertia section) [N].
  double rigid_track_p1_beta_v_N = 0.0;
};

/// What an inertial run (SimMode::inertial) adds: every contact phase,
/// flight and impact, and the comparisons with the lift-off model
/// (models/liftoff.h) and, with a compliant contact, with P1. The settings it
/// ran under (load, horizontal motion, flat approach, contact) are the model's.
/// The phases, flights, deviation from the kinematic path (z_reference is
/// CrossingModel::reference_height_m) and peak force are the phases
/// analysis's (ContactPhaseSummary, contact_phases.h).
struct InertialOutcome : ContactPhaseSummary {
  double static_load_N = 0.0;  ///< W = wheel load + M g, the static contact force [N]

  /// Index into trajectory.impacts of the impact at the joint: the largest
  /// one within 10 mm of the predicted two-point contact, else the first one
  /// after that (the wheel flew over it); -1 if none.
  int joint_impact_index = -1;
  /// Sum of all momentum jumps of the run (rigid contact), or of all force
  /// pulses' impulses (compliant) [N s].
  double total_impulse_Ns = 0.0;
  /// Summed horizontal contact impulse over the joint's impact [N s]; 0 without one.
  double joint_horizontal_impulse_Ns = 0.0;

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

  /// A contact spring (linear, or Hertz in a force run); empty: rigid contact.
  std::optional<CompliantContact> compliant;
  /// Force runs (Hertz contact, maybe an elastic track): P1, P2, the track's
  /// history and Jenkins's estimates (force_outcome.h).
  std::optional<ForceOutcome> forces;
};

/// Whether a run can vouch for its jump (a wrong number must never look
/// right). "suspect" runs exit 1 from the CLI.
struct SimVerdict {
  bool ok = false;
  std::string reason;  ///< empty when ok; otherwise every check that failed, "; "-separated
};

struct SimulationResult {
  /// What was simulated: joint, wheels, settings, the prediction it is
  /// compared with, load, rails, start (shared, so copies of a result and
  /// the renderer read the same rails).
  std::shared_ptr<const CrossingModel> model;

  /// The impact at the joint; empty when none was found. Inertial mode: the
  /// largest within 10 mm of the predicted one (InertialOutcome::joint_impact_index).
  std::optional<JointImpact> impact;
  /// The next impact after the joint's, within the run.
  std::optional<FollowingImpact> second_impact;
  /// Largest overlap between wheel and rail over the run [m]; resting
  /// contacts overlap by the slop by design.
  double max_penetration_m = 0.0;

  SimVerdict verdict;
  double wall_seconds = 0.0;  ///< building the world and stepping, one core [s]
  int steps = 0;
  int refined_steps = 0;
  Trajectory trajectory;  ///< every step, with contacts; trajectory.impacts lists all detected impacts

  std::variant<KinematicOutcome, InertialOutcome> outcome;

  /// The prediction the simulation is compared with: the governing slice of
  /// the wheel as simulated (a thin disc is simulated as a cylinder of width
  /// 2 * disc_half_width, whose inner face strikes first).
  const ImpactPrediction& prediction() const { return model->prediction; }
  /// The prediction for the scene's own wheel: for a thin disc the width-0
  /// one, which the simulation approaches as disc_half_width -> 0.
  const ImpactPrediction& scene_wheel_prediction() const {
    return model->thin_disc_prediction ? *model->thin_disc_prediction : model->prediction;
  }
  const InertialOutcome* inertial() const { return std::get_if<InertialOutcome>(&outcome); }
  bool impact_found() const { return impact.has_value(); }
  /// The measured jump (or pulse impulse) at the joint; NaN when none was found [N s].
  double impulse_Ns() const { return impact ? impact->impulse_Ns() : std::numeric_limits<double>::quiet_NaN(); }
  /// When the wheel first left the rails: after the impact (kinematic mode),
  /// the first flight of the run (inertial mode); empty if it never did [s, run time].
  std::optional<double> liftoff_time_s() const;
};

}  // namespace railjoint
