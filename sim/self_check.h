#pragma once
// The run's own check of its number (a wrong number must never
// look right). A kinematic crossing vouches for its jump only when the
// impact happened where the prediction puts it, the wheel came in on the
// predicted path, nothing else jumped first, the wheel never sank into the
// rail, and the two estimators of the jump (extrapolated velocities, summed
// contact impulses) agree. Each failed check adds its reason.

#include <vector>

#include "sim/simulation_result.h"

namespace railjoint {

/// A measured profile read through its points: the largest scatter of its
/// curvature at the contact (ProfileCurve::curvature_scatter_per_m) a force
/// run vouches for, as a fraction of the wheel's 1 / R (self_check.cpp).
inline constexpr double kMeasuredCurvatureScatter = 0.05;

struct SelfCheckLimits {
  /// Impact position against the prediction [m]. Located impacts land
  /// within nanometres; 0.1 mm still tells a hop or a sunk wheel.
  double impact_x_m = 1e-4;
  /// Largest overlap of wheel and rail [m] beyond the slop: the exact
  /// narrow phase holds it to round-off; a micrometre is a tunnelling step.
  double penetration_m = 1e-6;
  /// Approach velocity against the predicted slope, and the two jump
  /// estimators against each other, as a fraction of the predicted jump's
  /// velocity change [-]. The drift bound is the 1e-4 target; the
  /// contact sum integrates the load over the impact steps and was seen
  /// 1.6e-3 off on a good run with the disc at the rail-head edge, so it
  /// keeps the 0.5 % bound the regression tests use for it.
  double approach_drift = 1e-4;
  double estimator_disagreement = 5e-3;
  /// A rigid run's landing (any impact but the joint's) is stepped with a
  /// bias of (W dt)^2 / (2 J^2) of its jump J, W the load and dt the step it
  /// lands in (measured: self_check.cpp); above this the run cannot vouch
  /// for it. The random studies hold landings to 1e-3.
  double landing_step_bias = 1e-3;
};

/// Fills result.verdict for a kinematic run: `approach_slope` is the
/// predicted dz/dx of the centre just before the impact, `earlier_jumps` the
/// jumps found before the one at the predicted impact [N s each].
SimVerdict kinematic_self_check(const SimulationResult& result, const SimSettings& settings, double speed_m_per_s,
                                double mass_kg, double approach_slope, const std::vector<double>& earlier_jumps_Ns,
                                const SelfCheckLimits& limits = {});

/// Fills result.verdict for an inertial run: what it reports must have been
/// measured, not cut short or sunk into the rail. A joint impact was found;
/// a rigid contact never sank deeper than limits.penetration_m beyond the
/// slop and its jump's two estimators agree; every velocity and position
/// stayed finite; a run whose run-out followed the predicted flight
/// (sim.run_out_time left out) did not end in flight (the landing and the
/// total impulse would be missing a part). A run-out the user set may end
/// in flight: the report says so (InertialOutcome::ended_in_flight). A
/// rigid run's landings are large against the load's impulse over the step
/// they land in (limits.landing_step_bias).
SimVerdict inertial_self_check(const SimulationResult& result, const SimSettings& settings,
                               const SelfCheckLimits& limits = {});

}  // namespace railjoint
