#pragma once
// The recorded motion of the wheel: what the simulation writes and the
// renderer and the reports read. Plain data, no Bullet, so renders/ and the
// reports can use it without linking the physics.

#include <cstddef>
#include <vector>

#include <Eigen/Core>

namespace railjoint {

/// One contact point between the wheel and a rail at one recorded step.
struct ContactSample {
  Eigen::Vector3d point_on_rail_m = Eigen::Vector3d::Zero();  ///< world position of the contact on the rail [m]
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();          ///< unit normal, pointing from the rail into the wheel
  double distance_m = 0.0;                                    ///< signed gap (< 0: penetration) [m]
  double normal_impulse_Ns = 0.0;                             ///< impulse applied along the normal over the step [N s]
  int rail_index = 0;                                         ///< 0 = incoming rail, 1 = outgoing rail
  double normal_velocity_m_per_s = 0.0;  ///< rate of change of the gap, centre velocity along the normal (< 0: closing) [m/s]
  /// Friction impulse on the wheel over the step, in world axes [N s] (zero for frictionless contact).
  Eigen::Vector3d friction_impulse_Ns = Eigen::Vector3d::Zero();
  /// Total impulse the rail gave the wheel over the step [N s].
  Eigen::Vector3d impulse_Ns() const { return normal_impulse_Ns * normal + friction_impulse_Ns; }
};

/// The wheel's state at one recorded instant.
struct WheelSample {
  double time_s = 0.0;
  Eigen::Vector3d centre_m = Eigen::Vector3d::Zero();             ///< wheel centre (on the axle) [m]
  Eigen::Vector3d velocity_m_per_s = Eigen::Vector3d::Zero();     ///< centre velocity [m/s]
  /// The instant velocity_m_per_s belongs to [s] (crossing_world.h): the start
  /// of the step whose contacts set it, carried on by the steps in free
  /// flight after it; up to a step before time_s.
  double velocity_time_s = 0.0;
  /// The solver weighed the step's contacts against the load over the
  /// velocity's age, not over the step: a held contact let go in a step
  /// shorter than the one before, solved again (crossing_world.cpp).
  bool contacts_weighed_over_velocity_age = false;
  double spin_angle_rad = 0.0;                                    ///< rotation about the axle (y), positive rolling forward [rad]
  std::vector<ContactSample> contacts;
  /// Angular velocity about the axle (y), positive rolling forward [rad/s];
  /// v / R when the spin is locked (the wheel is taken to roll).
  double spin_rate_rad_per_s = 0.0;
};

/// The rails (bit per ContactSample::rail_index, below 32) whose contact the
/// solver took in the step that ended at `sample`.
inline unsigned solved_rails(const WheelSample& sample) {
  unsigned rails = 0;
  for (const ContactSample& c : sample.contacts) {
    if (c.normal_impulse_Ns > 0.0 && c.rail_index >= 0 && c.rail_index < 32) rails |= 1u << c.rail_index;
  }
  return rails;
}

/// The time the velocity change and the contact impulse of the step that
/// ended at samples[k] (k >= 1) cover [s]. A step that stays on the rails the
/// step before was on (rolling, turning about a corner) turns the velocity
/// from the tangent at that step's start to the tangent at its own: the time
/// between the two velocities' instants (velocity_time_s), the step before's
/// length. A held step cut short before a landing's first touch carries the
/// load over that whole time (crossing_world.cpp); over its own length it
/// read as 10x a pivot's v^2 / R. Any other step (a strike, a landing, a
/// flight): its own length.
inline double step_span_s(const std::vector<WheelSample>& samples, std::size_t k) {
  const unsigned now = solved_rails(samples[k]);
  const bool held = now != 0 && (now & ~solved_rails(samples[k - 1])) == 0;
  const double dated_s = samples[k].velocity_time_s - samples[k - 1].velocity_time_s;
  return held && dated_s > 0.0 ? dated_s : samples[k].time_s - samples[k - 1].time_s;
}

/// The time the contact impulses of the step that ended at samples[k]
/// (k >= 1) carry the load over [s], impulse / span being the contact force:
/// the step's length, or the velocity's age where the solver weighed them
/// over it (WheelSample::contacts_weighed_over_velocity_age; over the step
/// they read up to age / step times the force). Not step_span_s, which
/// dates every held step: a spring's or a shortening step on a plane
/// carries the load over its own length alone.
inline double contact_span_s(const std::vector<WheelSample>& samples, std::size_t k) {
  const double step_s = samples[k].time_s - samples[k - 1].time_s;
  if (!samples[k].contacts_weighed_over_velocity_age) return step_s;
  return samples[k].velocity_time_s - samples[k - 1].velocity_time_s;
}

/// A detected impact (a jump in the vertical velocity).
struct ImpactEvent {
  double time_s = 0.0;
  double wheel_x_m = 0.0;             ///< wheel centre x at the impact [m]
  double momentum_jump_Ns = 0.0;      ///< M (zdot+ - zdot-) [N s]
  Eigen::Vector3d contact_point_m = Eigen::Vector3d::Zero();  ///< where on the rail it struck [m]
  /// Summed horizontal (x) contact impulse over the impact steps [N s]: what
  /// the carrier absorbs (speed held) or what slows wheel + carrier (free).
  double horizontal_impulse_Ns = 0.0;
  /// The wheel had been in flight before it (a landing).
  bool landing = false;
  /// Largest summed vertical contact force during it [N]; compliant contact
  /// only (a rigid impact has no finite force).
  double peak_force_N = 0.0;
  std::size_t first_sample = 0;  ///< first sample of Trajectory::samples whose step carried it
  std::size_t last_sample = 0;   ///< last one
};

struct Trajectory {
  std::vector<WheelSample> samples;  ///< in increasing time
  std::vector<ImpactEvent> impacts;  ///< in increasing time
};

}  // namespace railjoint
