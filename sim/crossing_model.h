#pragma once
// What one crossing simulates, fixed before the first step: the joint, the
// wheel as the scene gives it and as Bullet simulates it, the settings, the
// prediction it is compared with, the load, the rail meshes, where the wheel
// starts and when the run ends. Built once (build_crossing_model), read by
// the stepping loop (crossing_run.h), the analyses (crossing_analysis.h) and
// the renderer, which draws these rails rather than building its own. No
// Bullet in this header.

#include <optional>
#include <vector>

#include <Eigen/Core>

#include "geometry/rail_joint_mesh.h"
#include "models/impact_prediction.h"
#include "models/parameters.h"
#include "sim/force_contact_geometry.h"
#include "sim/force_outcome.h"
#include "sim/sim_settings.h"

namespace railjoint {

/// Where and how fast the wheel starts.
struct WheelStart {
  Eigen::Vector3d centre_m = Eigen::Vector3d::Zero();
  double vertical_velocity_m_per_s = 0.0;
};

struct CrossingModel {
  JointParams joint;
  WheelParams wheel;            ///< as the scene gives it
  /// As simulated: a thin disc becomes the stand-in cylinder of
  /// wheel_as_simulated (setting_checks.h).
  WheelParams simulated_wheel;
  SimSettings settings;
  /// The prediction the simulation is compared with: the governing slice of
  /// the simulated wheel.
  ImpactPrediction prediction;
  /// For a thin-disc scene (wheel.width = 0): the width-0 prediction, which
  /// the stand-in's inner face reproduces (setting_checks.h).
  std::optional<ImpactPrediction> thin_disc_prediction;
  /// Downward force on the wheel besides its weight [N]: the preload that
  /// glues it to the rail (kinematic mode, resolved when automatic) or the
  /// static wheel load (inertial mode).
  double load_N = 0.0;
  RailJointMesh rails;
  WheelStart start;
  /// Simulated time after the predicted impact (sim.run_out_time, or derived
  /// from the predicted flight, see SimSettings::run_out_time_s) [s].
  double run_out_time_s = 0.0;
  double end_time_s = 0.0;  ///< simulated time at which the run ends [s]
  /// Force runs (elastic()): G of the Hertz contact [m/N^(2/3)], the static
  /// track state the run starts from, and how far the static load sinks the
  /// wheel below the kinematic path (Hertz approach and rail deflection) [m].
  double hertz_constant_m_per_N2_3 = 0.0;
  TrackState start_track;
  double static_sink_m = 0.0;
  /// The start's contact: the vertical part of its normal [-] and Hertz's
  /// part of static_sink_m, G (W / n_z)^(2/3) / n_z [m].
  double start_normal_z = 1.0;
  double start_hertz_sink_m = 0.0;
  /// The discrete track: where the wheel's contact starts, under which the
  /// track rests at the start, and how far the beam reaches either side of
  /// the joint (its free ends that far from the wheel's whole run) [m].
  double start_contact_x_m = 0.0;
  double discrete_track_half_length_m = 0.0;
  /// The discrete track at the start, every wheel's static load on it (a
  /// bogie's two, the leading one first): the rail's deflection under each
  /// wheel's contact [m] and its change per metre the wheels move on [-].
  /// start_track is the leading wheel's.
  struct RailUnderWheel {
    double z_m = 0.0;
    double dz_dx = 0.0;
  };
  std::vector<RailUnderWheel> start_rail_under_wheels;

  bool inertial() const { return settings.inertial() != nullptr; }
  /// A force run: Hertz's contact, maybe on an elastic track, stepped by
  /// elastic_crossing_run.h. Its settings, or null.
  const ElasticCrossingSettings* elastic() const { return inertial() ? settings.inertial()->elastic() : nullptr; }
  /// What a force run's contact geometry reads (force_contact_geometry.h).
  ForceContactInputs force_contact_inputs() const { return {joint, wheel, simulated_wheel, settings, rails}; }
  /// Inertial mode with a contact spring (linear or Hertz): no instant of impact to locate.
  bool compliant() const { return inertial() && settings.inertial()->compliant(); }
  /// Level rail before the dip [m]; inertial mode only (0 otherwise).
  double flat_approach_m() const { return inertial() ? settings.inertial()->flat_approach_m : 0.0; }
  /// Height of the path the kinematic model glues the centre to, at centre x
  /// [m]; a force run's lies static_sink_m below it.
  double reference_height_m(double wheel_x_m) const;
};

/// Axle load of a bogie wheel, about 14 times the wheel's weight [N].
inline constexpr double kDefaultPreload_N = 1e5;

/// The preload used when SimSettings::preload_N is empty: 2 M v^2 / R when
/// the jump happens on landing (the kinematic wheel first pivots about the
/// corner it rolls off, which needs M v^2 / R), else kDefaultPreload_N. Where
/// the general model holds (models/finite_width_wheel.h:
/// governing_slice_rule_holds is false) the path before the impact may bend
/// down anywhere along `approach_m` (a curved dip, a pivot into a gap):
/// at least 2 M v^2 k there, k its sharpest downward curvature.
double automatic_preload_N(const JointParams& joint, const ImpactPrediction& prediction, const WheelParams& wheel,
                           double approach_m);

/// Height of the kinematic reference path at centre x [m]: the glued wheel's
/// centre (kinematic_centre_height_m of the governing slice of `wheel`, the
/// wheel as simulated), and with a flat approach the flat before the dip and
/// the pivot over its entry kink.
double inertial_reference_height_m(const JointParams& joint, const WheelParams& wheel, double flat_approach_m,
                                   double wheel_x_m);

/// The simulated time after the predicted impact when sim.run_out_time is not
/// given: kDefaultRunOut_s, after the predicted landing in inertial mode when
/// the wheel is predicted to fly at the joint [s].
double derived_run_out_time_s(const JointParams& joint, const WheelParams& simulated_wheel,
                              const ImpactPrediction& prediction, const SimSettings& settings);

/// The predictions a crossing is compared with, made once: for the wheel as
/// simulated (simulated_wheel_of, setting_checks.h) and, for a thin disc
/// simulated as a cylinder, for the scene's own wheel.
struct CrossingPredictions {
  WheelParams simulated_wheel;
  ImpactPrediction simulated;
  std::optional<ImpactPrediction> thin_disc;
};

/// Makes them (predict_impact: throws InputError for a joint or wheel outside
/// the model). `scene_wheel`: the prediction for `wheel` when the caller
/// already has it (a scene read with SceneCheck::model), used, not made again.
CrossingPredictions predict_crossing(const JointParams& joint, const WheelParams& wheel, const SimSettings& settings,
                                     const ImpactPrediction* scene_wheel = nullptr);

/// The rail length [m] a simulation of these inputs needs: its start and its
/// end each within 0.4 L of the joint (check_sim_settings), with the run-out
/// derived when it is not given, and at least what the meshes need to carry
/// the wheel across the whole cut (minimum_rail_length_m). For a scene that
/// gives no joint.length.
double rail_length_needed_m(const JointParams& joint, const WheelParams& wheel, const SimSettings& settings);
/// The wheel centre's x up to which the incoming rail is straight [m]: a
/// curved dip's rail end droops over joint.dip_length D before the V and is
/// level beyond, so -D; a step down ends at the incoming rail's edge
/// (-gap / 2), over which the wheel pivots; a linear dip or a step up is
/// straight up to the strike (+infinity).
double straight_approach_end_x_m(const JointParams& joint);
/// How far before the predicted impact the wheel starts [m]:
/// sim.approach_distance; a force run on a curved dip or a step down that
/// far before straight_approach_end_x_m (on the level rail, where its static
/// state is an equilibrium: started inside the bend, the path's curvature loaded the
/// contact by M v^2 z'' from the first step, 3 % of P0 on a 0.3 m cosine
/// dip at 50 m/s, and P1 depended on the start, issue 37); on the discrete
/// track at least DiscreteTrack::start_lead_m (a start nearer the joint than
/// that left its moving state unsettled: a free hinge's P1 read 12 % high,
/// issue 41).
double start_distance_m(const JointParams& joint, const SimSettings& settings, double impact_wheel_x_m);
/// The same from predictions already made.
double rail_length_needed_m(const JointParams& joint, const WheelParams& wheel, const SimSettings& settings,
                            const CrossingPredictions& predictions);

/// Checks the inputs (check_simulation_inputs, setting_checks.h; throws
/// InputError naming the key) and builds the model: the one checked
/// crossing a run, its reports and its drawing read. `predictions`: made by
/// the caller for these inputs (predict_crossing), else made here.
CrossingModel build_crossing_model(const JointParams& joint, const WheelParams& wheel, const SimSettings& settings,
                                   const CrossingPredictions* predictions = nullptr);

}  // namespace railjoint
