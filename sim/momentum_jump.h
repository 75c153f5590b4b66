#pragma once
// Finding the impacts in a recorded trajectory and measuring each one's
// vertical momentum jump Delta p_z = M (zdot+ - zdot-) at the impact instant
// (sim/DESIGN.md "Measuring the momentum jump"). Pure function of the recorded
// samples: no Bullet, so it can be tested on hand-made trajectories.

#include <cstddef>
#include <limits>
#include <vector>

#include <Eigen/Core>

#include "sim/trajectory.h"

namespace railjoint {

struct JumpDetection {
  double mass_kg = 750.0;
  /// Constant vertical external force on the wheel (gravity + preload, < 0) [N].
  double vertical_force_N = 0.0;
  /// A step whose vertical acceleration exceeds this is part of an impact
  /// [m/s^2]. Smooth motion (rolling on a slope, pivoting about a corner at
  /// v^2/R, free flight under the preload) stays far below it.
  double impact_acceleration_m_per_s2 = 1e5;
  /// Steps next to an impact whose acceleration exceeds this still belong to
  /// it (partial impulses as the overlap builds up) [m/s^2].
  double smooth_acceleration_m_per_s2 = 1e4;
  /// A step whose velocity changes by at least coarse_jump [m/s] at a mean
  /// acceleration above coarse_acceleration [m/s^2] is an impact whatever its
  /// length. With coarse fixed steps the whole jump falls into one step: its
  /// mean acceleration (jump / step) can sit below impact_acceleration
  /// although no smooth motion changes the velocity that fast. Infinite: off.
  double coarse_jump_m_per_s = std::numeric_limits<double>::infinity();
  double coarse_acceleration_m_per_s2 = std::numeric_limits<double>::infinity();
  /// An impact must change the momentum by at least this [N s], in its
  /// largest step and net (very short steps make tiny velocity noise look
  /// like a large acceleration; a flickering contact gives a kick and its
  /// reversal).
  double min_jump_Ns = 1.0;
  /// The same for a landing after a flight (landing_after_flight in
  /// momentum_jump.cpp), which no flickering contact or short step mimics [N s].
  double min_landing_jump_Ns = 1.0;
  /// Impact steps closer than this in time belong to one impact [s]: the
  /// solver may resolve a strike over a few steps with quiet ones between.
  double merge_window_s = 2e-5;
  /// Signed gap at which the wheel, as modelled, touches the rail [m]
  /// (minus the slop: the Bullet wheel is enlarged by it). Used to date the
  /// impact inside its step.
  double touch_distance_m = 0.0;
  /// Samples fitted on each side of the jump, and samples skipped next to
  /// it. Three and none: the located impact is resolved in one step (its
  /// neighbours are clean), and a short fit does not reach across the start
  /// of a pivot just before a landing (a line through the level roll and the
  /// pivot missed the approach velocity by 5 % on a pivot of seven steps).
  int fit_samples = 3;
  int skip_samples = 0;
};

struct MomentumJump {
  double jump_Ns = 0.0;              ///< M (zdot+ - zdot-), both sides fitted linearly and extrapolated to time_s
  /// Summed vertical contact impulses over the impact steps + external force
  /// * duration, with each side's smooth motion from its last sample to the
  /// impact instant taken out by that side's fitted acceleration.
  double from_contacts_Ns = 0.0;
  /// Impact instant: when the struck contact's gap passed the touching gap.
  /// Bullet applies a step's impulse at the step's start (it detects, solves,
  /// then integrates), so this is the start of the first impact step, moved
  /// back by the overlap found there over the closing speed.
  double time_s = 0.0;
  double wheel_x_m = 0.0;            ///< wheel centre x at time_s
  double zdot_before_m_per_s = 0.0;  ///< fitted, at time_s
  double zdot_after_m_per_s = 0.0;   ///< fitted, at time_s
  double xdot_before_m_per_s = 0.0;  ///< horizontal velocity, fitted the same way (changes only if it is free)
  double xdot_after_m_per_s = 0.0;
  /// Summed horizontal (x) components of the contact impulses over the impact steps [N s].
  double horizontal_impulse_Ns = 0.0;
  std::size_t first_sample = 0;      ///< first sample whose step carried the impact
  std::size_t last_sample = 0;       ///< last one
  int struck_rail = -1;              ///< rail index of the contact with the largest vertical impulse
  Eigen::Vector3d struck_point_m = Eigen::Vector3d::Zero();  ///< where it struck (point on that rail)
  /// Mean of the closed contacts on the other rail just before the impact
  /// (the point the wheel leaves); NaN if there were none (landing).
  Eigen::Vector3d left_point_m = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
};

/// The detection settings for a wheel of mass M [kg] at horizontal speed v
/// [m/s] and radius R [m] under a constant vertical force [N], touching the
/// rail at touch_distance [m]. Smooth motion accelerates at most by a pivot
/// (v^2 / R) or by free flight under the load (|F| / M); an impact resolved
/// over a fine step is orders above both; over a coarse one it is still
/// above both and changes the velocity by more than 1 % of v in one step.
JumpDetection jump_detection_for(double mass_kg, double speed_m_per_s, double radius_m, double vertical_force_N,
                                 double touch_distance_m);

/// All impacts in time order. Samples need increasing, distinct times.
std::vector<MomentumJump> find_momentum_jumps(const Trajectory& trajectory, const JumpDetection& detection);

/// First time after `after_sample` at which the wheel has had no closed
/// contact (gap <= 0) for `sustained_samples` samples in a row; negative if never.
double find_liftoff_time_s(const Trajectory& trajectory, std::size_t after_sample, int sustained_samples = 3);

}  // namespace railjoint
