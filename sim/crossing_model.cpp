#include "sim/crossing_model.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "models/joint_flight.h"
#include "models/kinematic_trajectory.h"
#include "models/finite_width_wheel.h"
#include "models/rail_top.h"
#include "models/slice_profile.h"
#include "models/wheel_rail_envelope.h"
#include "sim/discrete_track.h"
#include "sim/force_contact_geometry.h"
#include "sim/hertz_law.h"
#include "sim/rail_surface.h"
#include "sim/setting_checks.h"

namespace railjoint {

namespace {
// The sharpest downward bend of the kinematic path over the approach
// [x* - approach, x*) [1/m]: second differences of its height at 64 points,
// h = 0.1 mm (the heights are exact to ~1e-16 m: a noise of 1e-8 /m).
double approach_curvature_per_m(const JointParams& joint, const WheelParams& wheel, double impact_x_m,
                                double approach_m) {
  constexpr int kPoints = 64;
  constexpr double h = 1e-4;
  const KinematicPath path(joint, wheel);
  double sharpest = 0.0;
  for (int i = 0; i < kPoints; ++i) {
    const double x = impact_x_m - 2.0 * h - (approach_m - 2.0 * h) * i / (kPoints - 1);
    const double bend = -(path.centre_height_m(x + h) - 2.0 * path.centre_height_m(x) + path.centre_height_m(x - h)) / (h * h);
    sharpest = std::max(sharpest, bend);
  }
  return sharpest;
}
}  // namespace

double automatic_preload_N(const JointParams& joint, const ImpactPrediction& prediction, const WheelParams& wheel,
                           double approach_m) {
  const double Mv2 = wheel.mass_kg * wheel.speed_m_per_s * wheel.speed_m_per_s;
  if (!governing_slice_rule_holds(joint, wheel)) {
    double k = approach_curvature_per_m(joint, wheel, prediction.impact_wheel_x_m, approach_m);
    // A pivot about the incoming rail's edge up to the impact (a landing, a
    // drop into the gap) bends the path at 1 / R however short it is: the
    // scan's 0.8 mm spacing misses one of 0.2 mm (a 1:32 cone landing on a
    // crown flew off it under 100 kN and landed 1 % soft).
    if (rail_support(joint, wheel, 0, prediction.impact_wheel_x_m).at_cut_edge) k = std::max(k, 1.0 / wheel.radius_m);
    return std::max(kDefaultPreload_N, 2.0 * Mv2 * k);
  }
  if (prediction.on_landing) {
    // Before a landing the kinematic wheel pivots about the corner it rolls
    // off (radius R): that needs a downward acceleration v^2 / R; twice that
    // keeps it on the arc (sim/DESIGN.md "What was measured with Bullet": it flies off otherwise).
    return 2.0 * wheel.mass_kg * wheel.speed_m_per_s * wheel.speed_m_per_s / wheel.radius_m;
  }
  // Otherwise the path before the impact is straight: any load keeps the
  // wheel on it, and a small one matters less when a contact flickers open
  // for a step (the wheel falls by F / M * dt meanwhile).
  return kDefaultPreload_N;
}

double inertial_reference_height_m(const JointParams& joint, const WheelParams& wheel, double flat_approach_m,
                                   double wheel_x_m) {
  double z = kinematic_centre_height_m(joint, wheel, wheel_x_m);
  if (flat_approach_m > 0.0) {
    const double x_kink = -0.5 * joint.length_m;
    const double h = flat_approach_height_m(joint);
    const ProfileSegment flat{{x_kink - flat_approach_m, h}, {x_kink, h}};
    z = std::max(z, segment_support(flat, wheel.radius_m, wheel_x_m).centre_z_m);
  }
  return z;
}

double CrossingModel::reference_height_m(double wheel_x_m) const {
  return inertial_reference_height_m(joint, simulated_wheel, flat_approach_m(), wheel_x_m) - static_sink_m;
}

namespace {
// The corner model of predict_joint_flight is the thesis's joint (a struck
// corner, straight tops); on the analytic tops a cone's struck slice or a
// curved dip's bend also make the wheel fly, where it predicted none or a
// shorter flight (2 % of random inertial strikes ended in flight). Here the
// path itself decides: where it bends down faster than the load can pull
// the wheel (-v^2 h'' > W / M just after the strike) the wheel leaves with
// the path's slope and flies under W / M until the parabola meets the path
// again. That meeting is bracketed by steps that start at 1 mm and grow by
// half each (a 50 m flight in 25 steps, where a march in 1 mm took 50,000
// heights) and bisected to 1 um. A bracket that steps over a touch and back
// finds a later meeting, never an earlier one: the run-out it sets is only
// ever longer than the first landing needs.
double path_flight_landing_x_m(const JointParams& joint, const WheelParams& wheel, const ImpactPrediction& prediction,
                               double load_N) {
  JointParams long_rails = joint;
  long_rails.length_m = 1e4;
  const KinematicPath path(long_rails, wheel);
  const double v = wheel.speed_m_per_s;
  const double g = load_N / wheel.mass_kg;
  const double x0 = prediction.impact_wheel_x_m;
  constexpr double h = 1e-5;
  const double bend =
      -(path.centre_height_m(x0 + 3.0 * h) - 2.0 * path.centre_height_m(x0 + 2.0 * h) + path.centre_height_m(x0 + h)) /
      (h * h);
  if (!(v * v * bend > g)) return x0;
  const double z0 = path.centre_height_m(x0);
  const double s0 = path.centre_slope(x0, +1);
  const auto flying = [&](double x) {
    const double t = (x - x0) / v;
    return z0 + s0 * (x - x0) - 0.5 * g * t * t > path.centre_height_m(x);
  };
  constexpr double kLongest_m = 50.0;
  double lo = x0;
  double step = 1e-3;
  double hi = x0 + step;
  while (flying(hi)) {
    if (hi >= x0 + kLongest_m) return hi;
    lo = hi;
    step *= 1.5;
    hi = std::min(hi + step, x0 + kLongest_m);
  }
  while (hi - lo > 1e-6) {
    const double mid = 0.5 * (lo + hi);
    (flying(mid) ? lo : hi) = mid;
  }
  return hi;
}
}  // namespace

double derived_run_out_time_s(const JointParams& joint, const WheelParams& simulated_wheel,
                              const ImpactPrediction& prediction, const SimSettings& settings) {
  const InertialSettings* inertial = settings.inertial();
  if (!inertial) return kDefaultRunOut_s;
  // A force run lasts past the P2 peak whatever the flight.
  if (const ElasticCrossingSettings* elastic = inertial->elastic()) return elastic->run_out_time_s;
  const double load_N = inertial->wheel_load_N + simulated_wheel.mass_kg * kStandardGravity_m_per_s2;
  const JointFlight flight = predict_joint_flight(joint, simulated_wheel, prediction, load_N);
  double landing_x_m = flight.flies ? flight.landing_x_m : prediction.impact_wheel_x_m;
  if (needs_analytic_rail_top(joint, simulated_wheel)) {
    landing_x_m = std::max(landing_x_m, path_flight_landing_x_m(joint, simulated_wheel, prediction, load_N));
  }
  const double to_landing_m = std::max(0.0, landing_x_m - prediction.impact_wheel_x_m);
  return to_landing_m / simulated_wheel.speed_m_per_s + kDefaultRunOut_s;
}

CrossingPredictions predict_crossing(const JointParams& joint, const WheelParams& wheel, const SimSettings& settings,
                                     const ImpactPrediction* scene_wheel) {
  CrossingPredictions p;
  p.simulated_wheel = simulated_wheel_of(joint, wheel, settings);
  const bool stand_in = p.simulated_wheel.width_m != wheel.width_m;
  const auto of_scene_wheel = [&] { return scene_wheel ? *scene_wheel : predict_impact(joint, wheel); };
  p.simulated = stand_in ? predict_impact(joint, p.simulated_wheel) : of_scene_wheel();
  if (stand_in) p.thin_disc = of_scene_wheel();
  return p;
}

namespace {
// How much further back a bogie's trailing wheel starts and ends than the
// leading one (0 for one wheel; bogie_settings.h).
double trailing_reach_m(const SimSettings& settings) {
  const InertialSettings* inertial = settings.inertial();
  const ElasticCrossingSettings* elastic = inertial ? inertial->elastic() : nullptr;
  return elastic ? elastic->trailing_reach_m() : 0.0;
}
}  // namespace

double straight_approach_end_x_m(const JointParams& joint) {
  // A step down: the incoming rail's edge, which the wheel then pivots over.
  if (joint.kind == JointKind::step) {
    return joint.step_height_m < 0.0 ? cut_x_m(joint, 0.0, 0) : std::numeric_limits<double>::infinity();
  }
  if (joint.dip_shape == DipShape::linear) return std::numeric_limits<double>::infinity();
  return -joint.dip_length_m;
}

double start_distance_m(const JointParams& joint, const SimSettings& settings, double impact_wheel_x_m) {
  const InertialSettings* inertial = settings.inertial();
  const ElasticCrossingSettings* elastic = inertial ? inertial->elastic() : nullptr;
  double lead_m = settings.approach_distance_m;
  if (!elastic) return lead_m;
  // On the level rail the wheel's contact lies under its centre: the centre
  // at the bend's start has its contact there.
  const double bend_x_m = straight_approach_end_x_m(joint);
  if (bend_x_m < impact_wheel_x_m) lead_m += impact_wheel_x_m - bend_x_m;
  if (elastic->discrete_track) lead_m = std::max(lead_m, DiscreteTrack::start_lead_m(*elastic->discrete_track));
  return lead_m;
}

double rail_length_needed_m(const JointParams& joint, const WheelParams& wheel, const SimSettings& settings) {
  return rail_length_needed_m(joint, wheel, settings, predict_crossing(joint, wheel, settings));
}

double rail_length_needed_m(const JointParams& joint, const WheelParams& wheel, const SimSettings& settings,
                            const CrossingPredictions& predictions) {
  const WheelParams& simulated = predictions.simulated_wheel;
  const ImpactPrediction& prediction = predictions.simulated;
  const double run_out_s = settings.run_out_time_s.value_or(derived_run_out_time_s(joint, simulated, prediction, settings));
  // Both ends measured from x = 0, with the impact's offset; 1 % more than
  // the checks' 0.4 L so the derived length passes them.
  const double trailing_m = trailing_reach_m(settings);
  const double before_m = start_distance_m(joint, settings, prediction.impact_wheel_x_m) -
                          std::min(0.0, prediction.impact_wheel_x_m) + trailing_m;
  const double after_m = run_out_s * wheel.speed_m_per_s + std::max(0.0, prediction.impact_wheel_x_m) + trailing_m;
  // And the rails the mesh needs to carry the wheel across the whole cut
  // (check_joint_geometry): on a 1 deg cut the cut alone reaches 1.15 m
  // along the track across a 20 mm head.
  return std::max(1.01 * std::max(before_m, after_m) / 0.4, minimum_rail_length_m(joint, wheel));
}

namespace {

// A force run starts in its static state on the incoming slope: the Hertz
// contact along the face normal (its z part n_z = cos gamma) carries
// N = W / n_z, so the wheel sinks by G N^(2/3) / n_z; the rail mass sits
// W / k_pad + W / k_ballast below its unloaded place, the sleeper W / k_ballast
// (the discrete track: its static line under every wheel's load).
// Started there, every force balances and the approach is exact.
void place_on_static_track(CrossingModel& model, double slope) {
  const ElasticCrossingSettings& elastic = *model.elastic();
  const double W = model.settings.inertial()->wheel_load_N + model.wheel.mass_kg * kStandardGravity_m_per_s2;
  // Hertz's constant at the start's contact (force_contact_geometry.h); on
  // the analytic tops the normal also leans across with the head.
  const ForceContact start = force_start_contact(model.force_contact_inputs(), model.start.centre_m);
  model.hertz_constant_m_per_N2_3 = start.contact.found ? start.hertz.hertz_constant_m_per_N2_3
                                                        : elastic.contact.hertz_constant_m_per_N2_3.value_or(
                                                              default_hertz_constant_m_per_N2_3(model.wheel.radius_m));
  const double n_z = start.contact.found && runs_on_analytic_rail_tops(model.joint, model.wheel, model.settings)
                         ? start.contact.normal.z()
                         : 1.0 / std::sqrt(1.0 + slope * slope);
  model.start_normal_z = n_z;
  model.start_hertz_sink_m = hertz_approach_m(model.hertz_constant_m_per_N2_3, W / n_z) / n_z;
  model.static_sink_m = model.start_hertz_sink_m;
  if (elastic.track) {
    model.start_track.sleeper_z_m = -W / elastic.track->support.ballast_stiffness_N_per_m;
    model.start_track.rail_z_m = model.start_track.sleeper_z_m - W / elastic.track->support.pad_stiffness_N_per_m;
    model.static_sink_m -= model.start_track.rail_z_m;
  }
  if (elastic.discrete_track) {
    const DiscreteTrackSettings& t = *elastic.discrete_track;
    // A bogie's trailing wheel starts axle_spacing further back, and the
    // leading one runs on as far while the trailing one crosses.
    const double trailing_m = elastic.trailing_reach_m();
    const double end_x =
        model.prediction.impact_wheel_x_m + model.run_out_time_s * model.wheel.speed_m_per_s + trailing_m;
    model.discrete_track_half_length_m = DiscreteTrack::half_length_for_run_m(
        t, std::max(std::abs(model.start.centre_m.x() - trailing_m), std::abs(end_x)));
    // The contact's foot on the incoming slope, R n below the centre.
    model.start_contact_x_m = model.start.centre_m.x() + model.wheel.radius_m * slope * n_z;
    // The rail under a moving wheel sinks as the static deflection under it
    // changes (towards a hinged joint, over a sleeper bay): the wheel starts
    // with that rate besides its path's, so its contact starts unstrained.
    // A bogie's trailing wheel stands on the same rail axle_spacing behind,
    // and its load moves the rail under the leading one too.
    DiscreteTrack track(t, model.discrete_track_half_length_m);
    std::vector<DiscreteTrack::PointLoad> loads{{W, model.start_contact_x_m}};
    if (elastic.bogie) loads.push_back({W, model.start_contact_x_m - elastic.bogie->axle_spacing_m});
    model.start_rail_under_wheels.clear();
    for (const DiscreteTrack::LineUnderLoad& l : track.static_line_under(loads)) {
      model.start_rail_under_wheels.push_back({l.z_m, l.dz_dx});
    }
    const CrossingModel::RailUnderWheel& line = model.start_rail_under_wheels.front();
    model.start.vertical_velocity_m_per_s += model.wheel.speed_m_per_s * line.dz_dx;
    model.start_track.rail_z_m = line.z_m;
    model.start_track.sleeper_z_m = track.nearest_sleeper_m(model.start_contact_x_m);
    model.static_sink_m -= model.start_track.rail_z_m;
  }
  model.start.centre_m.z() -= model.static_sink_m;
}

}  // namespace

CrossingModel build_crossing_model(const JointParams& joint, const WheelParams& wheel, const SimSettings& settings,
                                   const CrossingPredictions* predictions) {
  check_simulation_inputs(joint, wheel, settings);
  CrossingPredictions made;
  if (!predictions) {
    made = predict_crossing(joint, wheel, settings);
    predictions = &made;
  }
  CrossingModel model;
  model.joint = joint;
  model.wheel = wheel;
  model.settings = settings;
  model.simulated_wheel = predictions->simulated_wheel;
  const WheelParams& simulated = model.simulated_wheel;
  model.prediction = predictions->simulated;
  model.thin_disc_prediction = predictions->thin_disc;
  model.load_N = model.inertial() ? settings.inertial()->wheel_load_N
                                  : settings.kinematic()->preload_N.value_or(automatic_preload_N(
                                        joint, model.prediction, simulated, settings.approach_distance_m));

  RailJointMeshOptions mesh_options;
  mesh_options.flat_approach_m = model.flat_approach_m();
  model.rails = build_rail_joint_mesh(joint, mesh_options);

  // Start on the flat half way along it, or on the incoming slope
  // approach_distance before the predicted impact, with the matching
  // vertical velocity. A compliant contact starts compressed by its static
  // load: the spring along the normal (tilted by gamma) carries
  // W / cos(gamma), which sinks the centre by W / (k cos^2 gamma).
  const double v = wheel.speed_m_per_s;
  double slope = 0.0;
  if (model.flat_approach_m() > 0.0) {
    const double x0 = -0.5 * joint.length_m - 0.5 * model.flat_approach_m();
    model.start.centre_m = Eigen::Vector3d(x0, simulated.lateral_m, flat_approach_height_m(joint) + wheel.radius_m);
  } else {
    const double lead_m = start_distance_m(joint, settings, model.prediction.impact_wheel_x_m);
    if (lead_m > settings.approach_distance_m && !(lead_m < 0.4 * joint.length_m)) {
      const DiscreteTrackSettings* beam = model.elastic()->discrete_track ? &*model.elastic()->discrete_track : nullptr;
      const std::string why =
          beam && lead_m == DiscreteTrack::start_lead_m(*beam)
              ? "a force run on the discrete track starts " + setting_number(lead_m) +
                    " m before the joint (two decay lengths of its static line, so the track's moving state has "
                    "settled)"
              : "a force run starts sim.approach_distance before its rail stops being straight (a curved dip's "
                "bend, a step down's edge), " +
                    setting_number(lead_m) + " m before the predicted impact (in static equilibrium)";
      throw InputError("joint.length", "must be >= " + setting_number(rail_length_needed_m(joint, wheel, settings, *predictions)) +
                                           " m: " + why + "; got " + setting_number(joint.length_m) + " m");
    }
    const double x0 = model.prediction.impact_wheel_x_m - lead_m;
    model.start.centre_m = Eigen::Vector3d(x0, simulated.lateral_m, kinematic_centre_height_m(joint, simulated, x0));
    slope = kinematic_centre_slope(joint, simulated, x0, +1);
  }
  model.start.vertical_velocity_m_per_s = v * slope;
  if (const LinearContactSettings* spring = model.inertial() ? settings.inertial()->linear_contact() : nullptr) {
    const double static_load_N = settings.inertial()->wheel_load_N + wheel.mass_kg * kStandardGravity_m_per_s2;
    const double cos2 = 1.0 / (1.0 + slope * slope);
    model.start.centre_m.z() -= static_load_N / (spring->stiffness_N_per_m * cos2);
  }
  model.run_out_time_s =
      settings.run_out_time_s.value_or(derived_run_out_time_s(joint, simulated, model.prediction, settings));
  if (model.elastic()) place_on_static_track(model, slope);
  if (!settings.run_out_time_s && !(model.run_out_time_s * v < 0.4 * joint.length_m)) {
    const std::string why = model.elastic()
                                ? " m to carry the force run's " +
                                      setting_number(model.elastic()->run_out_time_s * 1e3) + " ms run-out, past P2"
                                : " m for the wheel to land back on the outgoing rail after its predicted "
                                  "flight";
    throw InputError("joint.length",
                     "must be >= " + setting_number(rail_length_needed_m(joint, wheel, settings, *predictions)) + why +
                         " (or set sim.run_out_time [s] to end the run earlier); got " +
                         setting_number(joint.length_m) + " m");
  }
  // A bogie's trailing wheel, axle_spacing behind, strikes that much later
  // and needs the same run-out past its impact (its P2 window).
  const double trailing_m = trailing_reach_m(settings);
  const double lead_m = start_distance_m(joint, settings, model.prediction.impact_wheel_x_m);
  if (trailing_m > 0.0 && !(lead_m + trailing_m < 0.4 * joint.length_m &&
                            model.run_out_time_s * v + trailing_m < 0.4 * joint.length_m)) {
    throw InputError("joint.length", "must be >= " +
                                         setting_number(rail_length_needed_m(joint, wheel, settings, *predictions)) +
                                         " m to carry the bogie's trailing wheel vehicle.axle_spacing = " +
                                         setting_number(trailing_m) + " m behind the leading one from its start to "
                                         "its run-out (leave joint.length out to have it derived); got " +
                                         setting_number(joint.length_m) + " m");
  }
  model.end_time_s =
      (model.prediction.impact_wheel_x_m - model.start.centre_m.x() + trailing_m) / v + model.run_out_time_s;
  return model;
}

}  // namespace railjoint
