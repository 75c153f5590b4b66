#pragma once
// The Bullet world of one crossing: two static rail meshes (incoming and
// outgoing rail end) and the wheel, an implicit cylinder carried at constant
// horizontal speed (sim/DESIGN.md "What the simulation must hold"; inertial mode
// may free the speed and the spin and make the contact compliant). Owns every
// Bullet object; steps and reports the wheel's state and contacts. Knows
// nothing about impacts: that is momentum_jump.h's job.

#include <memory>
#include <vector>

#include <Eigen/Core>

#include "geometry/triangle_mesh.h"
#include "models/parameters.h"
#include "sim/crossing_model.h"
#include "sim/exact_wheel_rail_algorithm.h"
#include "sim/rail_surface.h"
#include "sim/sim_settings.h"
#include "sim/trajectory.h"

class btBroadphaseInterface;
class btCollisionDispatcher;
class btCollisionShape;
class btCylinderShape;
class btDefaultCollisionConfiguration;
class btDiscreteDynamicsWorld;
class btRigidBody;
class btSequentialImpulseConstraintSolver;
class btTriangleMesh;
struct btTriangleInfoMap;
class btBvhTriangleMeshShape;
class btDefaultMotionState;

namespace railjoint {

class CrossingDynamicsWorld;  // crossing_world.cpp

/// Everything that changes when the world steps: enough to step again from
/// here (the rails never move; contacts are found afresh every step).
struct WorldState {
  double time_s = 0.0;
  double spin_angle_rad = 0.0;
  double velocity_time_s = 0.0;
  unsigned held_rails = 0;  ///< rails (bit per index) the next step holds the wheel on
  double hold_gap_m = 0.0;
  Eigen::Vector3d centre_m = Eigen::Vector3d::Zero();
  Eigen::Vector4d orientation_xyzw = Eigen::Vector4d(0, 0, 0, 1);
  Eigen::Vector3d velocity_m_per_s = Eigen::Vector3d::Zero();
  Eigen::Vector3d angular_velocity_rad_per_s = Eigen::Vector3d::Zero();
};

class CrossingWorld {
 public:
  /// `rails` are the incoming (index 0) and outgoing (index 1) rails.
  /// `wheel.width_m` must be > 0 here (the caller replaces a thin disc by a
  /// cylinder of small width). `preload_N` is the resolved downward force
  /// besides gravity (inertial mode: settings.wheel_load_N). In inertial mode
  /// the settings also pick the horizontal motion, the spin and the contact
  /// compliance (sim_settings.h).
  CrossingWorld(const std::vector<RailSurface>& rails, const WheelParams& wheel, const SimSettings& settings,
                double preload_N, const WheelStart& start);
  ~CrossingWorld();
  CrossingWorld(const CrossingWorld&) = delete;
  CrossingWorld& operator=(const CrossingWorld&) = delete;

  /// Advances by dt_s: holds the horizontal speed (unless inertial mode frees
  /// it) and applies the preload (inertial mode: the wheel load) before the
  /// step, as the carrier would.
  void step(double dt_s);

  double time_s() const { return time_s_; }
  /// Current state. Its contacts are those the solver used in the step that
  /// ended now: gap and normal at the start of that step (Bullet detects
  /// collisions before it integrates), impulse applied during it.
  WheelSample sample() const;

  /// Saves and restores the wheel's state, so a step that overshot an
  /// event can be taken again shorter (event location).
  WorldState state() const;
  void restore(const WorldState& state);

  /// The contacts at the current configuration, as the next step's collision
  /// detection will find them (no impulses: nothing is solved). Replaces the
  /// contacts sample() reads: take the sample first.
  std::vector<ContactSample> probe_contacts();

  /// Constant vertical external force on the wheel (gravity + preload) [N], < 0.
  double vertical_external_force_N() const;

  const btCollisionShape& wheel_shape() const;

 private:
  /// The wheel-rail points in the dispatcher's manifolds, with the impulses
  /// the last solve applied to them.
  std::vector<ContactSample> read_contacts() const;

  WheelParams wheel_params_;
  SimSettings settings_;
  double preload_N_ = 0.0;
  double shape_radius_m_ = 0.0;
  double time_s_ = 0.0;
  double start_x_m_ = 0.0;
  double spin_angle_rad_ = 0.0;
  /// The instant the wheel's velocity belongs to (see step()) [s].
  double velocity_time_s_ = 0.0;
  /// Rails whose contact acted in the last step, held on to in the next
  /// across gaps up to hold_gap_m_ (crossing_world.cpp, CrossingDynamicsWorld).
  unsigned held_rails_ = 0;
  double hold_gap_m_ = 0.0;
  bool compliant_ = false;        ///< inertial mode with a contact stiffness
  bool horizontal_free_ = false;  ///< inertial mode, horizontal speed not held
  bool spin_free_ = false;        ///< inertial mode with friction: the wheel spins about its axle

  std::unique_ptr<btDefaultCollisionConfiguration> configuration_;
  std::unique_ptr<btCollisionDispatcher> dispatcher_;
  std::unique_ptr<ExactWheelRailRegistration> exact_narrow_phase_;  ///< null: Bullet's GJK / EPA
  std::unique_ptr<btBroadphaseInterface> broadphase_;
  std::unique_ptr<btSequentialImpulseConstraintSolver> solver_;
  std::unique_ptr<btDiscreteDynamicsWorld> world_;
  CrossingDynamicsWorld* hard_world_ = nullptr;  ///< world_ when contacts are hard (not compliant)

  std::vector<RailSurface> rail_geometry_;  ///< the rails as the exact narrow phase reads them
  std::vector<std::unique_ptr<btTriangleMesh>> rail_meshes_;
  std::vector<std::unique_ptr<btTriangleInfoMap>> rail_edge_infos_;
  std::vector<std::unique_ptr<btBvhTriangleMeshShape>> rail_shapes_;
  std::vector<std::unique_ptr<btRigidBody>> rails_;

  std::unique_ptr<btCylinderShape> wheel_shape_;
  std::unique_ptr<btDefaultMotionState> wheel_motion_;
  std::unique_ptr<btRigidBody> wheel_;
};

}  // namespace railjoint
