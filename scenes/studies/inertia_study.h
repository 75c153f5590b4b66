#pragma once
// Where the kinematic model stops holding: the inertial simulation
// (SimMode::inertial, the wheel pressed on by its weight and the thesis's
// 112.5 kN wheel load only) swept over speed, lateral position and junction
// angle, next to the kinematic jump; the simulated lift-off speed against the
// pivot model (models/liftoff.h) found by bisection; and the peak force of a
// compliant contact against the P1 estimate (sim/impact_force_estimate.h).

#include <string>
#include <vector>

#include "models/impact_prediction.h"
#include "scenes/studies/csv_files.h"
#include "support/case_pool.h"

namespace railjoint {

/// One crossing of the sweep.
struct InertiaSweepPoint {
  double theta_deg = 0.0;
  double speed_m_per_s = 0.0;
  double lateral_m = 0.0;
  ImpactScenario scenario = ImpactScenario::one;  ///< of the simulated 1 mm disc
  bool on_landing = false;
  double kinematic_jump_Ns = 0.0;  ///< exact analytic jump (horizontal speed held) of the governing slice
  double first_jump_Ns = 0.0;      ///< the simulated jump at the joint (NaN if none)
  /// The next impact after the joint's if it is a landing after a flight, else 0.
  double landing_jump_Ns = 0.0;
  double total_impulse_Ns = 0.0;   ///< all jumps of the crossing
  int impacts = 0;
  bool liftoff = false;            ///< simulated flight anywhere in the run
  bool liftoff_predicted = false;  ///< the pivot model says v > v_c at the joint's pivot
  double pivot_liftoff_speed_m_per_s = 0.0;  ///< v_c of that pivot (NaN in scenario 1)
  /// Pivot model + ballistic flight: how far above the kinematic centre path
  /// the wheel would rise after leaving the pivot (0: it does not leave it;
  /// NaN in scenario 1). Strike: it leaves A at once with the exact zdot+ if
  /// v > v_c(alpha). Step down: it leaves the corner where the pivot demand
  /// first exceeds the load, cos^3(phi*) = M v^2 / (W R), phi* in [beta/2, alpha).
  /// Near the transition y_t (alpha -> beta/2) lift-off is predicted but
  /// rises less than the simulation's ~2 um detection.
  double predicted_clearance_m = 0.0;
  double flight_time_s = 0.0;      ///< longest flight
  double apex_height_m = 0.0;      ///< its apex above its lift-off point
  double max_deviation_m = 0.0;    ///< from the kinematic centre path
  bool ended_in_flight = false;
  double wall_s = 0.0;
};

/// Simulated lift-off speed of one pivot, bracketed by bisection on v.
struct LiftoffThresholdPoint {
  std::string name;
  double theta_deg = 0.0;
  double lateral_m = 0.0;
  double flat_approach_m = 0.0;  ///< > 0: the entry kink of the dip
  double pivot_angle_rad = 0.0;
  double static_load_N = 0.0;    ///< W = wheel load + M g
  double model_speed_m_per_s = 0.0;
  double sim_below_m_per_s = 0.0;  ///< highest speed found without lift-off
  double sim_above_m_per_s = 0.0;  ///< lowest speed found with lift-off
  int runs = 0;
};

/// Compliant contact: simulated peak force against P1 (rigid track) with the
/// two velocity changes it can be fed: the dip's beta v and the kinematic jump.
struct PeakForcePoint {
  double theta_deg = 0.0;
  double lateral_m = 0.0;
  double speed_m_per_s = 0.0;
  int scenario = 0;  ///< 1 or 2 (of the governing slice)
  double static_load_N = 0.0;
  double stiffness_N_per_m = 0.0;
  double kinematic_jump_Ns = 0.0;
  double jump_velocity_change_m_per_s = 0.0;  ///< kinematic_jump / M [m/s]
  double peak_force_N = 0.0;
  double p1_rigid_track_N = 0.0;  ///< Jenkins et al. with m_e -> infinity, 2 alpha = beta: P0 + beta v sqrt(k M)
  /// The same with the exact kinematic velocity change Delta p / M instead of
  /// beta v. Equal to the above in scenario 1; larger in scenario 2, where the
  /// wheel strikes the cut edge at the angle of its radius to the corner.
  double p1_from_jump_N = 0.0;
  /// Scenario 2: how long the rigid wheel pivots about the cut edge before it
  /// rolls onto the far rail's top, (x_A - x_w + R sin(beta/2)) / v [s]; 0 in
  /// scenario 1 (no pivot).
  double edge_pivot_time_s = 0.0;
  /// Rise time of the contact spring, (pi/2) sqrt(M / k) [s]. A pivot much
  /// shorter than this is over before the force peaks: the spring then feels
  /// the net velocity change beta v, not the jump at the edge.
  double spring_quarter_period_s = 0.0;
};

struct InertiaStudy {
  bool quick = false;
  double wheel_load_N = 0.0;
  double joint_length_m = 0.0;
  std::vector<InertiaSweepPoint> sweep;
  std::vector<LiftoffThresholdPoint> thresholds;
  std::vector<PeakForcePoint> peaks;
  double wall_s = 0.0;
};

/// Full: theta 30/45/60/90 deg x v 10..50 m/s (9) x y_w -18..18 mm (25),
/// bisections for 7 pivots, 10 compliant runs (5 speeds in each scenario); a
/// minute or two on one core. Quick: theta 30 deg x 3 speeds x 3 positions,
/// one bisection, one compliant run per scenario at 50 m/s. Each crossing
/// (each bisection) on one of parallel.jobs threads.
InertiaStudy run_inertia_study(bool quick, const ParallelRuns& parallel = {});

/// inertia_sweep.csv, inertia_thresholds.csv, inertia_peaks.csv.
void write_inertia_csvs(const InertiaStudy& study, const CsvFiles& files);

/// Markdown summary: what holds, where lift-off starts, thresholds, P1.
std::string inertia_report(const InertiaStudy& study);

}  // namespace railjoint
