#pragma once
// Numerical and physical switches of the Bullet crossing scene: the [sim]
// section of a scene file. Plain header without Bullet, so scenes/ can read
// and range-check it without linking the physics. The defaults are the
// settings that meet the accuracy target (|error| <= 0.5 % against the exact
// kinematic jump, sim/DESIGN.md "What the simulation must hold").

#include <cmath>
#include <optional>
#include <variant>

#include "sim/elastic_track_settings.h"

namespace railjoint {

enum class SimMode {
  /// The kinematic model's assumptions held by the scene: carrier holds the
  /// horizontal speed, only vertical motion and spin, frictionless plastic
  /// contact, wheel started on the incoming slope and pressed on by a preload.
  kinematic,
  /// The wheel as in service: pressed on only by its weight and the static
  /// wheel load, so it may leave the rail. Each of the kinematic model's other
  /// assumptions is a switch (fields marked "inertial mode"): friction with a
  /// spinning wheel, restitution, a free horizontal speed with a carrier mass,
  /// a flat approach before the dip, a compliant contact. With all switches at
  /// their defaults the scene differs from the kinematic one only in the load.
  inertial,
};

/// Horizontal motion of the wheel in inertial mode.
enum class HorizontalMotion {
  held,  ///< the carrier (bogie) holds the speed whatever the contact pushes
  free,  ///< the contact's horizontal impulse changes the speed of wheel + carrier mass
};

/// How wheel-rail contacts are found.
enum class NarrowPhase {
  /// The exact wheel-rail contact (sim/cylinder_rail_contact.h) registered
  /// with Bullet's dispatcher: exact normals and gaps.
  exact,
  /// Bullet's generic GJK / EPA on the cylinder and each triangle: normals
  /// at the struck edge noisy by ~1.5e-4 rad (kept to show why).
  bullet,
};

/// What only a kinematic run has.
struct KinematicSettings {
  /// Downward force on the wheel besides gravity [N]; keeps the wheel on the
  /// rail before the impact. Following a pivot arc (before a jump on landing,
  /// the step-down side) needs more than M v^2 / R. Empty: automatic, see
  /// automatic_preload_N in crossing_model.h (2 M v^2 / R on landing, else 100 kN).
  std::optional<double> preload_N;
};

/// A linear spring along the contact normal (a scene's [contact] law = "linear").
struct LinearContactSettings {
  /// Stiffness [N/m] (Bullet's per-object contact stiffness, solved
  /// implicitly together with the damping): turns each jump into a force
  /// history with a finite peak.
  double stiffness_N_per_m = 1.4e9;
  /// Damper in parallel with the spring [N s/m]. 0 here (Jenkins's P1 is for
  /// an undamped spring, as the inertia study uses it); a scene's [contact]
  /// law = "linear" defaults to critical_contact_damping_N_s_per_m.
  double damping_N_s_per_m = 0.0;
};

/// What only an inertial run has (SimMode::inertial): the wheel pressed on
/// by its weight and the wheel load, and each of the kinematic model's other
/// assumptions as a switch.
struct InertialSettings {
  /// Static wheel load besides the wheel's own weight [N]: the axle load's
  /// share carried by this wheel through its axle box. Default: thesis
  /// table 6.1, 225 kN axle load / 2. The static contact force is this plus M g.
  double wheel_load_N = 112.5e3;
  HorizontalMotion horizontal = HorizontalMotion::held;
  /// Free horizontal motion: the mass moving horizontally with the wheel
  /// besides the wheel itself [kg]. Empty: wheel_load / g, the train mass
  /// whose weight the wheel carries.
  std::optional<double> carrier_mass_kg;
  /// Radius of gyration of the wheel about its axle [m], used when friction
  /// makes it spin (friction > 0). Empty: R / sqrt(2), a solid disc (I = M R^2 / 2).
  std::optional<double> radius_of_gyration_m;
  /// Level rail before the dip [m] (geometry/rail_joint_mesh.h): the wheel
  /// starts on it, half way along, and crosses the entry kink of the V.
  /// 0: start on the incoming slope as in kinematic mode.
  double flat_approach_m = 0.0;
  /// The contact: rigid (std::monostate), a linear spring, or a force run's
  /// Hertz contact ([contact] law = "hertz"), maybe on an elastic track
  /// ([track]) under a suspension ([vehicle]), stepped by elastic_crossing_run.h.
  std::variant<std::monostate, LinearContactSettings, ElasticCrossingSettings> contact;
  const LinearContactSettings* linear_contact() const { return std::get_if<LinearContactSettings>(&contact); }
  LinearContactSettings* linear_contact() { return std::get_if<LinearContactSettings>(&contact); }
  const ElasticCrossingSettings* elastic() const { return std::get_if<ElasticCrossingSettings>(&contact); }
  ElasticCrossingSettings* elastic() { return std::get_if<ElasticCrossingSettings>(&contact); }
  /// A contact spring, linear or Hertz: no instant of impact to locate.
  bool compliant() const { return !std::holds_alternative<std::monostate>(contact); }
  /// Sample step of a force run (an elastic() contact) [s]: one step a sample, and on an elastic track over the
  /// impact's pulse steps of at most refined_time_step (pulse_window.h). Velocity Verlet,
  /// second order (vertical_mass.h): P1 on scenes/forces/lumped_track.toml is 4.4e-6 below its
  /// converged value at 4e-6 s (7.1e-5 with every step at 4e-6 s), with about 114 samples
  /// across the P1 pulse; on seeded random crossings within 4e-6 on the elastic tracks, 6e-6 on the rigid one
  /// (docs/forces.md, "The step").
  double force_time_step_s = 4e-6;
};

struct SimSettings {
  /// Coarse step [s]: used while the wheel rolls on a plane or flies and no
  /// contact gap is about to close.
  double time_step_s = 1e-4;
  /// Fine step [s] used around an impact. The jump is resolved to about
  /// v * dt of travel (sim/DESIGN.md "What was measured with Bullet": 1e-6 s gave 0.1-0.2 %).
  /// A force run (where the key is refused) steps its impact's pulse at most this long.
  double refined_time_step_s = 1e-6;
  /// Fine steps once a closing contact gap is below this [m]. Above it the
  /// step is cut to a quarter of the time the gap needs to close (never below the
  /// fine step), so the approach to an impact takes a handful of steps.
  double refine_distance_m = 1e-5;
  /// Keep the fine step this long after a gap closed, the velocity jumped,
  /// the wheel turned about a contact or neared the end of the incoming rail
  /// (both sides of a jump sampled finely for the extrapolation) [s].
  /// Empty: by mode, see refine_hold_in_use_s below.
  std::optional<double> refine_hold_s;

  /// Collision margin of the wheel cylinder and the rail meshes [m]. Bullet's
  /// default (0.04 m) is larger than the whole joint geometry.
  double margin_m = 1e-6;
  /// Contact breaking threshold [m]: gaps up to this are reported, so a
  /// closing gap is seen coming; only those below the processing threshold
  /// are solved.
  double contact_breaking_threshold_m = 2e-3;
  /// Linear slop [m]: resting contacts overlap by this much (deeper overlaps
  /// are pushed out by split impulse); the wheel radius is enlarged by it so
  /// the centre still rests at R above the rail.
  double slop_m = 0.0;
  /// Contacts with a signed gap up to this are solved [m]; an impact is
  /// located to the instant its gap reaches it (event_located_step.h), so the
  /// struck contact is solved that far before the touch, which turns its
  /// normal and leaves an error of about gap / (R (tan alpha + tan(beta/2))^2)
  /// in the jump: 6e-7 of the default scene's at 1e-9 m, 6e-9 at 1e-11 m
  /// (random scenes: scenario-2 median 2.7e-6 at 1e-9 m, 1.3e-8 at 1e-11 m).
  /// The exact narrow phase's gaps are exact to round-off (1e-16 m), and a
  /// contact the wheel rolls on or turns about is held across the gap a step
  /// opens (crossing_world.cpp), so nothing needs a larger one. With Bullet's
  /// own narrow phase, solve only overlapping contacts (a negative value
  /// below minus the margins): its closest-point (GJK) normal was 5 % off at
  /// the cut edge. Must lie above -slop, or resting contacts (overlap = slop)
  /// are dropped.
  double contact_processing_threshold_m = 1e-11;
  /// Split impulse (position correction kept out of the velocities) below
  /// this signed penetration [m]; 0 = always. Bullet's default is -0.04 m, so
  /// small overlaps become velocity kicks.
  double split_impulse_threshold_m = 0.0;
  /// Sequential-impulse iterations. Bullet's solver takes a contact's
  /// effective mass as 1/M whatever the body's linear factor, but with the
  /// horizontal speed held only the normal's vertical part n_z moves the
  /// wheel: each iteration closes n_z^2 of what is left, the rest shrinks by
  /// sin^2(phi) per iteration (phi: the normal from the vertical). On the
  /// thesis's 0.3 m step (phi = 45.6 deg) 10 iterations left 1.2e-3 of the
  /// jump (0.51^10), 30 left 3e-9; 100 leave nothing up to phi = 60 deg
  /// (0.75^100 = 3e-13). Two or three contacts: the iterations cost nothing
  /// measurable (study convergence).
  int solver_iterations = 100;
  /// Hold a contact the solver has taken as a hard velocity constraint (no
  /// speculative closing within the slop): with microsecond steps the
  /// penetration solver's distance noise otherwise became velocity noise.
  bool hard_contacts = true;

  double friction = 0.0;     ///< Coulomb coefficient [-]; 0 for the validation runs
  double restitution = 0.0;  ///< [-]; 0 (plastic) for the validation runs
  NarrowPhase narrow_phase = NarrowPhase::exact;
  /// Fix contact normals on internal triangle edges of the rail meshes
  /// (btAdjustInternalEdgeContacts). Only switched off to show why it is needed.
  bool internal_edge_fix = true;

  /// Half width of the cylinder that stands in for a thin disc (wheel.width = 0) [m].
  double disc_half_width_m = 5e-4;
  /// Horizontal travel of the wheel centre before the predicted impact [m].
  double approach_distance_m = 0.05;
  /// Simulated time after the predicted impact [s]. Empty: kDefaultRunOut_s,
  /// and in inertial mode that long after the predicted landing when the
  /// wheel is predicted to fly at the joint (models/joint_flight.h), so the
  /// run ends with the wheel back on the rail (CrossingModel::run_out_time_s).
  std::optional<double> run_out_time_s;

  /// The mode and what only it has.
  std::variant<KinematicSettings, InertialSettings> mode_settings;

  SimMode mode() const { return inertial() ? SimMode::inertial : SimMode::kinematic; }
  const KinematicSettings* kinematic() const { return std::get_if<KinematicSettings>(&mode_settings); }
  KinematicSettings* kinematic() { return std::get_if<KinematicSettings>(&mode_settings); }
  const InertialSettings* inertial() const { return std::get_if<InertialSettings>(&mode_settings); }
  InertialSettings* inertial() { return std::get_if<InertialSettings>(&mode_settings); }
  /// The inertial run's linear contact spring or force-run settings; null otherwise (and in kinematic mode).
  const LinearContactSettings* linear_contact() const { return inertial() ? inertial()->linear_contact() : nullptr; }
  const ElasticCrossingSettings* elastic() const { return inertial() ? inertial()->elastic() : nullptr; }
  LinearContactSettings* linear_contact() { return inertial() ? inertial()->linear_contact() : nullptr; }
  ElasticCrossingSettings* elastic() { return inertial() ? inertial()->elastic() : nullptr; }
  /// Switches to inertial mode (its defaults) unless already there; returns its part.
  InertialSettings& make_inertial() {
    if (!inertial()) mode_settings.emplace<InertialSettings>();
    return std::get<InertialSettings>(mode_settings);
  }
  /// Switches to kinematic mode unless already there; returns its part.
  KinematicSettings& make_kinematic() {
    if (!kinematic()) mode_settings.emplace<KinematicSettings>();
    return std::get<KinematicSettings>(mode_settings);
  }
};

/// Simulated time after the predicted impact, or after the predicted
/// landing, when sim.run_out_time is not given [s]: enough for the jump fit
/// (three steps) and to see the wheel settle.
inline constexpr double kDefaultRunOut_s = 2e-3;

/// Standard gravity used by the simulation [m/s^2].
inline constexpr double kStandardGravity_m_per_s2 = 9.81;

/// The carrier mass used with free horizontal motion [kg]: the setting, or
/// wheel_load / g when it is empty.
inline double resolved_carrier_mass_kg(const InertialSettings& settings) {
  return settings.carrier_mass_kg.value_or(settings.wheel_load_N / kStandardGravity_m_per_s2);
}

inline const char* to_string(SimMode mode) {
  switch (mode) {
    case SimMode::kinematic:
      return "kinematic";
    case SimMode::inertial:
      return "inertial";
  }
  return "unknown";
}

inline const char* to_string(NarrowPhase narrow_phase) {
  switch (narrow_phase) {
    case NarrowPhase::exact:
      return "exact";
    case NarrowPhase::bullet:
      return "bullet";
  }
  return "unknown";
}

inline const char* to_string(HorizontalMotion motion) {
  switch (motion) {
    case HorizontalMotion::held:
      return "held";
    case HorizontalMotion::free:
      return "free";
  }
  return "unknown";
}

/// The fine-step hold in use [s]. Kinematic: 2e-5 s, which covers the 12
/// samples the jump fit reads after a jump (1.2e-5 s at the fine step), at
/// fewer steps than 5e-5 s (the same jump above about 25 m/s). Inertial:
/// 5e-5 s; there the fine steps after a strike also decide whether the
/// wheel lifts off (docs/convergence.md, "The fine-step hold").
inline double refine_hold_in_use_s(const SimSettings& settings) {
  return settings.refine_hold_s.value_or(settings.inertial() ? 5e-5 : 2e-5);
}

/// Critical damping of a contact spring k under the wheel's mass M,
/// 2 sqrt(k M) [N s/m]: the contact does not ring. Undamped, a linear contact
/// on a rigid track gives back the impact's energy and the wheel bounces off
/// the rail again and again (nothing else in the model takes it).
inline double critical_contact_damping_N_s_per_m(double stiffness_N_per_m, double wheel_mass_kg) {
  return 2.0 * std::sqrt(stiffness_N_per_m * wheel_mass_kg);
}

}  // namespace railjoint
