#include "sim/crossing_world.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>

#include <btBulletDynamicsCommon.h>
#include <BulletCollision/CollisionDispatch/btInternalEdgeUtility.h>
#include <BulletCollision/CollisionShapes/btTriangleInfoMap.h>

namespace railjoint {

namespace {

// Contact stiffness of the rails in compliant mode: rigid next to any wheel spring.
constexpr double kRigidStiffness_N_per_m = 1e30;
// How far above the processing threshold a suppressed compliant contact point is put [m].
constexpr double kSuppressedGap_m = 1e-9;
constexpr int kRailIndexBase = 1000;  // user index of rail bodies: base + 0 (incoming), base + 1 (outgoing)

// The rail index of a wheel-rail manifold's other body (out of 0..31 for a
// body that is not a rail).
int rail_index(const btPersistentManifold& manifold, const btCollisionObject* wheel) {
  const btCollisionObject* rail = manifold.getBody0() == wheel ? manifold.getBody1() : manifold.getBody0();
  return rail->getUserIndex() - kRailIndexBase;
}

// Contact breaking and processing thresholds are per manifold in Bullet and
// otherwise come from globals (gContactBreakingThreshold) scaled by the
// shapes' size. Setting them on every new manifold keeps them local to this world.
class CrossingDispatcher : public btCollisionDispatcher {
 public:
  CrossingDispatcher(btCollisionConfiguration* configuration, double breaking_m, double processing_m)
      : btCollisionDispatcher(configuration), breaking_m_(breaking_m), processing_m_(processing_m) {}

  btPersistentManifold* getNewManifold(const btCollisionObject* b0, const btCollisionObject* b1) override {
    btPersistentManifold* manifold = btCollisionDispatcher::getNewManifold(b0, b1);
    manifold->setContactBreakingThreshold(breaking_m_);
    manifold->setContactProcessingThreshold(processing_m_);
    return manifold;
  }

 private:
  double breaking_m_;
  double processing_m_;
};

// A compliant contact (inertial mode) is one spring per rail. Bullet gives
// a spring to every contact point, and the wheel finds one point per mesh
// triangle it overlaps (two on a rail top split by its diagonal, more at the
// cut): the stiffness would count them. Only the deepest point of each
// wheel-rail manifold is solved; the others are moved above the processing
// threshold for this step.
class CompliantDynamicsWorld : public btDiscreteDynamicsWorld {
 public:
  using btDiscreteDynamicsWorld::btDiscreteDynamicsWorld;

 protected:
  void solveConstraints(btContactSolverInfo& info) override {
    btDispatcher* dispatcher = getDispatcher();
    for (int m = 0; m < dispatcher->getNumManifolds(); ++m) {
      btPersistentManifold* manifold = dispatcher->getManifoldByIndexInternal(m);
      const double threshold = manifold->getContactProcessingThreshold();
      int deepest = -1;
      for (int p = 0; p < manifold->getNumContacts(); ++p) {
        const double d = manifold->getContactPoint(p).getDistance();
        if (d <= threshold && (deepest < 0 || d < manifold->getContactPoint(deepest).getDistance())) deepest = p;
      }
      for (int p = 0; p < manifold->getNumContacts(); ++p) {
        btManifoldPoint& point = manifold->getContactPoint(p);
        if (p != deepest && point.getDistance() <= threshold) point.m_distance1 = threshold + kSuppressedGap_m;
      }
    }
    btDiscreteDynamicsWorld::solveConstraints(info);
  }
};

bool is_rail(const btCollisionObject* object) {
  return object->getUserIndex() >= kRailIndexBase;
}

// Bullet's contact-added hook: normals of contacts on internal edges of a
// triangle mesh (e.g. the diagonal of a flat face) are replaced by the face
// normal. Without it the wheel hops where it crosses a diagonal (sim/DESIGN.md
// "What was measured with Bullet": up to ~200 N s). Only called for bodies flagged CF_CUSTOM_MATERIAL_CALLBACK.
bool adjust_internal_edge_contact(btManifoldPoint& point, const btCollisionObjectWrapper* wrap0, int part0,
                                  int index0, const btCollisionObjectWrapper* wrap1, int part1, int index1) {
  if (is_rail(wrap0->getCollisionObject())) {
    btAdjustInternalEdgeContacts(point, wrap0, wrap1, part0, index0);
  } else if (is_rail(wrap1->getCollisionObject())) {
    btAdjustInternalEdgeContacts(point, wrap1, wrap0, part1, index1);
  }
  return true;  // return value is ignored by Bullet
}

}  // namespace

// Bullet's solver lets a contact with overlap below the slop close by
// (overlap - slop) within the step ("speculative" contact). With our 1e-6 s
// steps a distance noise of 1e-7 m (the penetration solver's, on a 0.5 m
// cylinder) became a 0.1 m/s velocity error, and the preload pulled the
// wheel into the rail in bumps. Once the solver takes a contact (gap at or
// below the processing threshold) it is therefore held as a hard velocity
// constraint: its overlap is read as at least the slop, so only deeper
// overlaps are pushed out (split impulse), none is allowed to close further.
//
// A contact that acted in the previous step is held on to: the wheel,
// moving along the tangent of a corner it turns about, ends each step
// (v dt)^2 / 2R off the arc (7 nm at 80 m/s and 1e-6 s), above the
// processing threshold. Left alone, that contact went unsolved every other
// step and the wheel fell freely under the load between solved ones, so
// neither its height nor its velocity stayed on the pivot. So before the
// solve the wheel is put back on such a rail, moved down by the gap
// (position only, like split impulse the other way), and the contact is
// solved at the configuration it left. Whether the wheel stays on the rail
// is still the solver's decision: the corner's normal has turned by v dt / R
// since the last step, so the velocity carries the outward v^2 dt / R the
// load must cancel; if it cannot (above the lift-off speed) the impulse is
// zero and the wheel flies from the next step on. Then the put-back is
// undone: the gap was the flight's first rise, not a step's drift off the
// arc, and taking it away lowered the flight by up to (v dt)^2 / 2 times the
// path's bend (1.6 nm after a strike onto a crown whose path bends at 20 g:
// a 0.15 um flight landed 9 um early and 0.5 % soft).
class CrossingDynamicsWorld : public btDiscreteDynamicsWorld {
 public:
  CrossingDynamicsWorld(btDispatcher* dispatcher, btBroadphaseInterface* broadphase, btConstraintSolver* solver,
                        btCollisionConfiguration* configuration, double slop_m)
      : btDiscreteDynamicsWorld(dispatcher, broadphase, solver, configuration), slop_m_(slop_m) {}

  /// The wheel, and for the next step the rails it is held on (bit per rail
  /// index), the largest gap it is put back across [m] and the velocity the
  /// load adds over the part of the velocity's age the step does not cover
  /// [m/s] (0 unless the step is shorter than the one before).
  void hold(btRigidBody* wheel, unsigned rails, double gap_m, double lag_load_dv_m_per_s) {
    wheel_ = wheel;
    held_rails_ = rails;
    hold_gap_m_ = gap_m;
    lag_load_dv_m_per_s_ = lag_load_dv_m_per_s;
  }

  /// Whether the last step's contact impulses carry the load over the
  /// velocity's age (the re-solve below stood), not over the step alone.
  bool weighed_over_velocity_age() const { return weighed_over_velocity_age_; }

 protected:
  void solveConstraints(btContactSolverInfo& info) override {
    btDispatcher* dispatcher = getDispatcher();
    weighed_over_velocity_age_ = false;
    const double drop_m = put_back_on_held_rails(*dispatcher);
    for (int m = 0; m < dispatcher->getNumManifolds(); ++m) {
      btPersistentManifold* manifold = dispatcher->getManifoldByIndexInternal(m);
      for (int p = 0; p < manifold->getNumContacts(); ++p) {
        btManifoldPoint& point = manifold->getContactPoint(p);
        if (point.getDistance() <= manifold->getContactProcessingThreshold() && point.getDistance() > -slop_m_) {
          point.m_distance1 = -slop_m_;
        }
      }
    }
    const btVector3 velocity_before = wheel_ != nullptr ? wheel_->getLinearVelocity() : btVector3(0, 0, 0);
    btDiscreteDynamicsWorld::solveConstraints(info);
    if (held_rails_ != 0 && lag_load_dv_m_per_s_ != 0.0 && rails_with_impulse(*dispatcher) == 0) {
      weigh_release_over_the_velocity_age(info, velocity_before);
    }
    if (drop_m > 0.0 && rails_with_impulse(*dispatcher) == 0) move_wheel_down(*dispatcher, -drop_m);
  }

 private:
  // The gap of a point along the rail -> wheel normal, and that normal's z.
  double normal_z(const btPersistentManifold& manifold, const btManifoldPoint& point) const {
    return manifold.getBody0() == wheel_ ? point.m_normalWorldOnB.z() : -point.m_normalWorldOnB.z();
  }

  // The held contact let go in a step shorter than the one before: its
  // normal turned by v dt_prev / R since the velocity was made tangent, and
  // the load over this step alone, a dt, was weighed against that outward
  // v^2 dt_prev / R (a step cut short to end at a landing's first touch
  // released a pivot the load holds: the approach velocity came 1e-5 of the
  // jump off the path). The load over the velocity's whole age, a dt_prev,
  // is what the uniform steps weigh it against: solved again with it, the
  // wheel stays on if that load holds it (the velocity then tangent, as in
  // any held step), else the first solve stands. It stands too where the
  // second solve strikes another rail (the lag's velocity would start that
  // contact a step early, with load never applied): the first solve took no
  // impulse anywhere, so none is left on the contacts.
  void weigh_release_over_the_velocity_age(btContactSolverInfo& info, const btVector3& velocity_before) {
    const btVector3 released = wheel_->getLinearVelocity();
    wheel_->setLinearVelocity(velocity_before + btVector3(0, 0, lag_load_dv_m_per_s_));
    btDiscreteDynamicsWorld::solveConstraints(info);
    const unsigned struck = rails_with_impulse(*getDispatcher());
    weighed_over_velocity_age_ = struck != 0 && (struck & ~held_rails_) == 0;
    if (weighed_over_velocity_age_) return;
    wheel_->setLinearVelocity(released);
    clear_impulses(*getDispatcher());
  }

  // The rails (bit per rail index) on which the last solve applied an impulse.
  unsigned rails_with_impulse(btDispatcher& dispatcher) const {
    unsigned rails = 0;
    for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
      const btPersistentManifold* manifold = dispatcher.getManifoldByIndexInternal(m);
      const int index = rail_index(*manifold, wheel_);
      for (int p = 0; p < manifold->getNumContacts(); ++p) {
        if (manifold->getContactPoint(p).getAppliedImpulse() == 0.0) continue;
        rails |= index >= 0 && index < 32 ? 1u << index : ~0u;  // not a rail: never held
      }
    }
    return rails;
  }

  static void clear_impulses(btDispatcher& dispatcher) {
    for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
      btPersistentManifold* manifold = dispatcher.getManifoldByIndexInternal(m);
      for (int p = 0; p < manifold->getNumContacts(); ++p) {
        btManifoldPoint& point = manifold->getContactPoint(p);
        point.m_appliedImpulse = 0.0;
        point.m_appliedImpulseLateral1 = 0.0;
        point.m_appliedImpulseLateral2 = 0.0;
      }
    }
  }

  // Moves the wheel down by drop_m (up where negative), and every contact's
  // gap with it.
  void move_wheel_down(btDispatcher& dispatcher, double drop_m) {
    btTransform transform = wheel_->getWorldTransform();
    transform.getOrigin().setZ(transform.getOrigin().z() - drop_m);
    wheel_->setWorldTransform(transform);
    for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
      btPersistentManifold* manifold = dispatcher.getManifoldByIndexInternal(m);
      for (int p = 0; p < manifold->getNumContacts(); ++p) {
        btManifoldPoint& point = manifold->getContactPoint(p);
        point.m_distance1 -= drop_m * normal_z(*manifold, point);
      }
    }
  }

  // The drop [m] the wheel was moved down by (0: not moved).
  double put_back_on_held_rails(btDispatcher& dispatcher) {
    if (held_rails_ == 0 || wheel_ == nullptr) return 0.0;
    // Per held rail its nearest point; the wheel moves down by the smallest
    // such gap, and only if every held rail is open (a rail it still
    // touches would be pushed into).
    double drop_m = std::numeric_limits<double>::infinity();
    unsigned seen = 0;
    for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
      btPersistentManifold* manifold = dispatcher.getManifoldByIndexInternal(m);
      const int index = rail_index(*manifold, wheel_);
      if (index < 0 || index >= 32 || ((held_rails_ >> index) & 1u) == 0) continue;
      for (int p = 0; p < manifold->getNumContacts(); ++p) {
        const btManifoldPoint& point = manifold->getContactPoint(p);
        const double nz = normal_z(*manifold, point);
        if (!(nz > 0.1)) continue;  // a side or cut face: nothing to put back on
        seen |= 1u << index;
        if (point.getDistance() <= manifold->getContactProcessingThreshold()) return 0.0;  // still touching
        drop_m = std::min(drop_m, point.getDistance() / nz);
      }
    }
    if (seen != held_rails_ || !(drop_m <= hold_gap_m_)) return 0.0;
    move_wheel_down(dispatcher, drop_m);
    return drop_m;
  }

  double slop_m_;
  btRigidBody* wheel_ = nullptr;
  unsigned held_rails_ = 0;
  double hold_gap_m_ = 0.0;
  double lag_load_dv_m_per_s_ = 0.0;
  bool weighed_over_velocity_age_ = false;
};

CrossingWorld::CrossingWorld(const std::vector<RailSurface>& rails, const WheelParams& wheel,
                             const SimSettings& settings, double preload_N, const WheelStart& start)
    : wheel_params_(wheel), settings_(settings), preload_N_(preload_N) {
  const InertialSettings* inertial = settings.inertial();
  // Bullet solves a linear contact spring itself; a force run's Hertz law is applied by elastic_crossing_run.
  const LinearContactSettings* spring = inertial ? inertial->linear_contact() : nullptr;
  compliant_ = spring != nullptr;
  horizontal_free_ = inertial && inertial->horizontal == HorizontalMotion::free;
  spin_free_ = inertial && settings.friction > 0.0;
  // Bullet's default pools hold 4096 manifolds and 4096 algorithms, touched
  // in full when built: 15-20 ms of page faults on the first crossings of a
  // process, ten times a whole run. A wheel on two rails needs a handful;
  // past the pool Bullet allocates from the heap.
  btDefaultCollisionConstructionInfo pools;
  pools.m_defaultMaxPersistentManifoldPoolSize = 64;
  pools.m_defaultMaxCollisionAlgorithmPoolSize = 64;
  configuration_ = std::make_unique<btDefaultCollisionConfiguration>(pools);
  dispatcher_ = std::make_unique<CrossingDispatcher>(configuration_.get(), settings.contact_breaking_threshold_m,
                                                     settings.contact_processing_threshold_m);
  if (settings.narrow_phase == NarrowPhase::exact) {
    exact_narrow_phase_ = std::make_unique<ExactWheelRailRegistration>(*dispatcher_);
  }
  broadphase_ = std::make_unique<btDbvtBroadphase>();
  solver_ = std::make_unique<btSequentialImpulseConstraintSolver>();
  // A compliant contact is a spring that must be allowed to compress: no
  // hard velocity constraint at the slop.
  if (compliant_) {
    world_ = std::make_unique<CompliantDynamicsWorld>(dispatcher_.get(), broadphase_.get(), solver_.get(),
                                                      configuration_.get());
  } else if (settings.hard_contacts) {
    auto world = std::make_unique<CrossingDynamicsWorld>(dispatcher_.get(), broadphase_.get(), solver_.get(),
                                                         configuration_.get(), settings.slop_m);
    hard_world_ = world.get();
    world_ = std::move(world);
  } else {
    world_ = std::make_unique<btDiscreteDynamicsWorld>(dispatcher_.get(), broadphase_.get(), solver_.get(),
                                                       configuration_.get());
  }
  world_->setGravity(btVector3(0, 0, -kStandardGravity_m_per_s2));

  btContactSolverInfo& info = world_->getSolverInfo();
  info.m_numIterations = settings.solver_iterations;
  // Split impulse keeps position correction out of the velocities; for a
  // compliant contact that correction is the spring force, so it must act on
  // the velocity (Bullet's contact ERP/CFM from stiffness and damping).
  info.m_splitImpulse = compliant_ ? 0 : 1;
  info.m_splitImpulsePenetrationThreshold = settings.split_impulse_threshold_m;
  info.m_linearSlop = settings.slop_m;

  // The exact narrow phase finds the face itself wherever a diagonal lies.
  const bool internal_edge_fix = settings.internal_edge_fix && !exact_narrow_phase_;
  // Bullet's hook is a process-wide global: set once, never written again
  // while other threads' worlds step (sweeps run a world per thread). It
  // only acts on bodies flagged CF_CUSTOM_MATERIAL_CALLBACK (below).
  static std::once_flag contact_hook_set;
  if (internal_edge_fix) std::call_once(contact_hook_set, [] { gContactAddedCallback = adjust_internal_edge_contact; });

  rail_geometry_ = rails;
  for (std::size_t r = 0; r < rails.size(); ++r) {
    const TriangleMesh& mesh = rails[r].mesh;
    // The mesh's own vertices and indices, as they are: addTriangle's
    // removal of duplicate vertices searches every vertex added so far, which
    // cost 40 ms (63 % of the run) on a curved dip's 64 x 20 crowned grid.
    // The builder shares each grid vertex already (geometry/rail_joint_mesh.cpp).
    auto triangles = std::make_unique<btTriangleMesh>(true, true);
    for (const Eigen::Vector3d& v : mesh.vertices_m) triangles->findOrAddVertex(btVector3(v.x(), v.y(), v.z()), false);
    for (const Eigen::Vector3i& t : mesh.triangles) triangles->addTriangleIndices(t[0], t[1], t[2]);
    auto shape = std::make_unique<btBvhTriangleMeshShape>(triangles.get(), true, true);
    shape->setMargin(settings.margin_m);
    auto edge_info = std::make_unique<btTriangleInfoMap>();
    // Bullet treats contacts within 0.1 m of a triangle edge as edge
    // contacts, here every contact on a 40 mm rail head, and then also bends
    // the normal at the real cut edge (scenario 2 at 45 deg: -0.21 % instead
    // of -0.13 %). A contact on a diagonal lies on it to within the margins.
    edge_info->m_edgeDistanceThreshold = 100.0 * settings.margin_m;
    if (internal_edge_fix) btGenerateInternalEdgeInfo(shape.get(), edge_info.get());

    btRigidBody::btRigidBodyConstructionInfo body_info(0.0, nullptr, shape.get());
    body_info.m_friction = 1.0;     // combined friction is the product: the wheel's value decides
    body_info.m_restitution = 1.0;  // likewise for restitution
    auto body = std::make_unique<btRigidBody>(body_info);
    body->setUserIndex(kRailIndexBase + static_cast<int>(r));
    body->setUserPointer(&rail_geometry_[r]);
    if (compliant_) {
      // Bullet puts the two objects' springs in series and adds the dampers:
      // a rigid rail (stiffness 1e30 N/m, no damper) leaves the wheel's values.
      body->setContactStiffnessAndDamping(kRigidStiffness_N_per_m, 0.0);
    }
    if (internal_edge_fix) {
      body->setCollisionFlags(body->getCollisionFlags() | btCollisionObject::CF_CUSTOM_MATERIAL_CALLBACK);
    }
    world_->addRigidBody(body.get());

    rail_meshes_.push_back(std::move(triangles));
    rail_edge_infos_.push_back(std::move(edge_info));
    rail_shapes_.push_back(std::move(shape));
    rails_.push_back(std::move(body));
  }

  // The wheel: an implicit cylinder, axle along y (Bullet's btCylinderShape
  // axis). Its half extents include the margin. Resting contacts overlap by
  // the slop and the rail surface is raised by the rail margin, so the radius
  // is R + slop - margin for the centre to rest at R above the rail top.
  shape_radius_m_ = wheel.radius_m + settings.slop_m - settings.margin_m;
  // A disc on analytic rail tops (sim/rail_surface.h) keeps the stand-in's
  // width for Bullet's shape: its narrow phase takes the disc as it is.
  const double half_width_m = wheel.width_m > 0.0 ? 0.5 * wheel.width_m : settings.disc_half_width_m;
  wheel_shape_ = std::make_unique<btCylinderShape>(btVector3(shape_radius_m_, half_width_m, shape_radius_m_));
  wheel_shape_->setMargin(settings.margin_m);

  btVector3 inertia(0, 0, 0);
  wheel_shape_->calculateLocalInertia(wheel.mass_kg, inertia);
  if (spin_free_) {
    // Spin about the axle (y) from the wheel's mass distribution; the other
    // axes stay locked, their values do not matter.
    const double k = inertial->radius_of_gyration_m.value_or(wheel.radius_m / std::sqrt(2.0));
    inertia.setY(wheel.mass_kg * k * k);
  }
  btTransform transform;
  transform.setIdentity();
  transform.setOrigin(btVector3(start.centre_m.x(), start.centre_m.y(), start.centre_m.z()));
  wheel_motion_ = std::make_unique<btDefaultMotionState>(transform);
  btRigidBody::btRigidBodyConstructionInfo wheel_info(wheel.mass_kg, wheel_motion_.get(), wheel_shape_.get(), inertia);
  wheel_info.m_friction = settings.friction;
  wheel_info.m_restitution = settings.restitution;
  wheel_info.m_linearDamping = 0.0;
  wheel_info.m_angularDamping = 0.0;
  wheel_ = std::make_unique<btRigidBody>(wheel_info);
  wheel_->setUserIndex(0);
  wheel_->setActivationState(DISABLE_DEACTIVATION);
  // The carrier: only vertical translation. Spin is locked too: with
  // frictionless contact it carries no force, but Bullet adds omega x r to
  // the contact velocity, and at the cut edge the penetration solver puts
  // the point off the line through the axle (the cylinder's rim corner):
  // a spinning wheel then stopped short of the kinematic jump (-8 % at
  // theta = 30 deg, y_w = 3 mm). The recorded spin angle is the rolling angle.
  //
  // Inertial mode may free the horizontal motion and the spin:
  // - free horizontal motion with a carrier of mass m_c: Bullet's solver
  //   applies a body's linear factor twice (its solver body's inverse mass is
  //   (1/M) * factor, and each impulse is scaled by the factor again), so a
  //   factor sqrt(M / (M + m_c)) along x makes contact impulses change v_x as
  //   for the mass M + m_c. No other horizontal force acts (load and gravity
  //   are vertical), so the factor touches nothing else;
  // - spin about the axle when friction can drive it, started rolling.
  double x_factor = 0.0;
  if (horizontal_free_) {
    x_factor = std::sqrt(wheel.mass_kg / (wheel.mass_kg + resolved_carrier_mass_kg(*inertial)));
  }
  wheel_->setLinearFactor(btVector3(x_factor, 0, 1));
  wheel_->setAngularFactor(btVector3(0, spin_free_ ? 1 : 0, 0));
  if (compliant_) {
    wheel_->setContactStiffnessAndDamping(spring->stiffness_N_per_m, spring->damping_N_s_per_m);
  }
  world_->addRigidBody(wheel_.get());
  wheel_->setLinearVelocity(btVector3(wheel.speed_m_per_s, 0, start.vertical_velocity_m_per_s));
  // A spinning wheel starts rolling along its path: |velocity| over the
  // radius it rolls on, the cylinder's surface with its margin, R + slop
  // (the margin is inside the half extents). Started on R + slop - margin it
  // slipped by margin / R = 2e-6 until friction, mu N dt per step, caught up.
  const double path_speed = std::hypot(wheel.speed_m_per_s, start.vertical_velocity_m_per_s);
  const double rolling_radius_m = wheel.radius_m + settings.slop_m;
  wheel_->setAngularVelocity(btVector3(0, spin_free_ ? path_speed / rolling_radius_m : 0.0, 0));
  start_x_m_ = start.centre_m.x();
}

CrossingWorld::~CrossingWorld() {
  if (world_) {
    world_->removeRigidBody(wheel_.get());
    for (auto& rail : rails_) world_->removeRigidBody(rail.get());
  }
}

const btCollisionShape& CrossingWorld::wheel_shape() const { return *wheel_shape_; }

double CrossingWorld::vertical_external_force_N() const {
  return -wheel_params_.mass_kg * kStandardGravity_m_per_s2 - preload_N_;
}

void CrossingWorld::step(double dt_s) {
  // Horizontal speed is out of the solver (linear factor z only) and set
  // here every step: the carrier holds it (sim/DESIGN.md "What was measured with Bullet":
  // better than a callback).
  // Free horizontal motion leaves it to the solver.
  if (!horizontal_free_) {
    const btVector3 velocity = wheel_->getLinearVelocity();
    wheel_->setLinearVelocity(btVector3(wheel_params_.speed_m_per_s, 0, velocity.z()));
  }
  wheel_->applyCentralForce(btVector3(0, 0, -preload_N_));
  // Fresh contacts every step. A persistent manifold keeps at most four
  // points and keeps points the wheel has rolled past (still within the
  // breaking threshold); with four of those it dropped the new resting
  // contact and the wheel fell under the preload for a whole step. The
  // cylinder needs no accumulated manifold: it can only move vertically.
  for (int m = 0; m < dispatcher_->getNumManifolds(); ++m) dispatcher_->getManifoldByIndexInternal(m)->clearManifold();
  const double start_s = time_s_;
  if (hard_world_ != nullptr) {
    // The velocity's age at the step's start: the last contact step's length
    // while the wheel is held (velocity_time_s_ is that step's start).
    const double age_s = start_s - velocity_time_s_;
    const double uncovered_s = age_s > dt_s * (1.0 + 1e-9) ? age_s - dt_s : 0.0;
    const double a_m_per_s2 = vertical_external_force_N() / wheel_params_.mass_kg;
    hard_world_->hold(wheel_.get(), held_rails_, hold_gap_m_, a_m_per_s2 * uncovered_s);
  }
  world_->stepSimulation(dt_s, 0, dt_s);
  time_s_ += dt_s;
  spin_angle_rad_ += wheel_->getAngularVelocity().y() * dt_s;

  // The rails whose contact acted in this step: held on to in the next
  // (CrossingDynamicsWorld), across the gap this step's motion along a
  // tangent can open, (v dt)^2 / 2R, twice over.
  unsigned acted = 0;
  for (int m = 0; m < dispatcher_->getNumManifolds(); ++m) {
    const btPersistentManifold* manifold = dispatcher_->getManifoldByIndexInternal(m);
    const int index = rail_index(*manifold, wheel_.get());
    for (int p = 0; p < manifold->getNumContacts(); ++p) {
      const btManifoldPoint& point = manifold->getContactPoint(p);
      if (point.getDistance() <= manifold->getContactProcessingThreshold() && point.getAppliedImpulse() != 0.0 &&
          index >= 0 && index < 32) {
        acted |= 1u << index;
      }
    }
  }
  const double travel_m = wheel_params_.speed_m_per_s * dt_s;
  held_rails_ = acted;
  hold_gap_m_ = travel_m * travel_m / wheel_params_.radius_m + std::max(0.0, settings_.contact_processing_threshold_m);
  const bool contact_acted = acted != 0;

  // Bullet's step applies the forces, solves the contacts of the starting
  // configuration and then moves the wheel with the velocity it got: where a
  // contact acted, that velocity is the starting configuration's (the load's
  // effect over the step taken out by the contact). A step in free flight
  // adds the load's a dt to it, so it belongs to the instant one such step
  // later: the velocity keeps the lag its last contact gave it, which is the
  // length of that step, whatever the flight's steps are.
  if (contact_acted) {
    velocity_time_s_ = start_s;
  } else if (!compliant_) {
    // Free flight: the wheel moved by v_k dt with v_k = v(tau_k), tau_k =
    // tau_{k-1} + dt, where the exact motion from t_{k-1} moves by
    // v(t_{k-1}) dt + a dt^2 / 2. The difference, a dt (lag - dt / 2) with
    // lag = t_{k-1} - tau_{k-1}, is added, so the flight's heights are
    // exact under the constant load and the landing comes when it should
    // (without it a 17 ms flight after 1e-4 s steps landed 130 um low and
    // 1.2 % soft). A spring contact's flights are left to Bullet.
    const double lag_s = start_s - velocity_time_s_;
    velocity_time_s_ += dt_s;
    const double a_m_per_s2 = vertical_external_force_N() / wheel_params_.mass_kg;
    btTransform transform = wheel_->getWorldTransform();
    transform.getOrigin().setZ(transform.getOrigin().z() + a_m_per_s2 * dt_s * (lag_s - 0.5 * dt_s));
    wheel_->setWorldTransform(transform);
    wheel_->setInterpolationWorldTransform(transform);
    wheel_motion_->setWorldTransform(transform);
  } else {
    velocity_time_s_ += dt_s;
  }
}

WorldState CrossingWorld::state() const {
  WorldState out;
  out.time_s = time_s_;
  out.spin_angle_rad = spin_angle_rad_;
  out.velocity_time_s = velocity_time_s_;
  out.held_rails = held_rails_;
  out.hold_gap_m = hold_gap_m_;
  const btTransform& transform = wheel_->getWorldTransform();
  const btVector3& origin = transform.getOrigin();
  const btQuaternion rotation = transform.getRotation();
  const btVector3& velocity = wheel_->getLinearVelocity();
  const btVector3& spin = wheel_->getAngularVelocity();
  out.centre_m = Eigen::Vector3d(origin.x(), origin.y(), origin.z());
  out.orientation_xyzw = Eigen::Vector4d(rotation.x(), rotation.y(), rotation.z(), rotation.w());
  out.velocity_m_per_s = Eigen::Vector3d(velocity.x(), velocity.y(), velocity.z());
  out.angular_velocity_rad_per_s = Eigen::Vector3d(spin.x(), spin.y(), spin.z());
  return out;
}

void CrossingWorld::restore(const WorldState& state) {
  time_s_ = state.time_s;
  spin_angle_rad_ = state.spin_angle_rad;
  velocity_time_s_ = state.velocity_time_s;
  held_rails_ = state.held_rails;
  hold_gap_m_ = state.hold_gap_m;
  const Eigen::Vector4d& q = state.orientation_xyzw;
  const btTransform transform(btQuaternion(q.x(), q.y(), q.z(), q.w()),
                              btVector3(state.centre_m.x(), state.centre_m.y(), state.centre_m.z()));
  wheel_->setWorldTransform(transform);
  wheel_->setInterpolationWorldTransform(transform);
  wheel_motion_->setWorldTransform(transform);
  const Eigen::Vector3d& v = state.velocity_m_per_s;
  const Eigen::Vector3d& w = state.angular_velocity_rad_per_s;
  wheel_->setLinearVelocity(btVector3(v.x(), v.y(), v.z()));
  wheel_->setAngularVelocity(btVector3(w.x(), w.y(), w.z()));
  wheel_->setInterpolationLinearVelocity(btVector3(v.x(), v.y(), v.z()));
  wheel_->setInterpolationAngularVelocity(btVector3(w.x(), w.y(), w.z()));
  wheel_->clearForces();
}

std::vector<ContactSample> CrossingWorld::probe_contacts() {
  for (int m = 0; m < dispatcher_->getNumManifolds(); ++m) dispatcher_->getManifoldByIndexInternal(m)->clearManifold();
  world_->performDiscreteCollisionDetection();
  // Fresh manifold points carry no applied impulse: nothing is solved here.
  return read_contacts();
}

std::vector<ContactSample> CrossingWorld::read_contacts() const {
  std::vector<ContactSample> contacts;
  const btVector3& velocity = wheel_->getLinearVelocity();
  const int manifolds = dispatcher_->getNumManifolds();
  for (int m = 0; m < manifolds; ++m) {
    const btPersistentManifold* manifold = dispatcher_->getManifoldByIndexInternal(m);
    const bool wheel_is_a = manifold->getBody0() == wheel_.get();
    if (!wheel_is_a && manifold->getBody1() != wheel_.get()) continue;
    for (int p = 0; p < manifold->getNumContacts(); ++p) {
      const btManifoldPoint& point = manifold->getContactPoint(p);
      ContactSample c;
      // normalWorldOnB points from B to A; we want rail -> wheel.
      const btVector3 normal = wheel_is_a ? point.m_normalWorldOnB : -point.m_normalWorldOnB;
      const btVector3& on_rail = wheel_is_a ? point.getPositionWorldOnB() : point.getPositionWorldOnA();
      c.point_on_rail_m = Eigen::Vector3d(on_rail.x(), on_rail.y(), on_rail.z());
      c.normal = Eigen::Vector3d(normal.x(), normal.y(), normal.z());
      c.distance_m = point.getDistance();
      // Points the solver skipped (gap above the processing threshold) keep a
      // stale impulse from an earlier step: they applied none in this one.
      c.normal_impulse_Ns =
          point.getDistance() <= manifold->getContactProcessingThreshold() ? point.getAppliedImpulse() : 0.0;
      c.rail_index = rail_index(*manifold, wheel_.get());
      if (point.getDistance() <= manifold->getContactProcessingThreshold()) {
        // Bullet's friction directions act on body A; flip them for the wheel as B.
        const btVector3 friction = point.m_appliedImpulseLateral1 * point.m_lateralFrictionDir1 +
                                   point.m_appliedImpulseLateral2 * point.m_lateralFrictionDir2;
        const btVector3 on_wheel = wheel_is_a ? friction : -friction;
        c.friction_impulse_Ns = Eigen::Vector3d(on_wheel.x(), on_wheel.y(), on_wheel.z());
      }
      // The gap changes with the centre's motion only: spinning an implicit
      // cylinder about its axle does not move its surface.
      c.normal_velocity_m_per_s = velocity.dot(normal);
      contacts.push_back(c);
    }
  }
  return contacts;
}

WheelSample CrossingWorld::sample() const {
  WheelSample s;
  s.time_s = time_s_;
  s.velocity_time_s = velocity_time_s_;
  s.contacts_weighed_over_velocity_age = hard_world_ != nullptr && hard_world_->weighed_over_velocity_age();
  const btTransform& transform = wheel_->getWorldTransform();
  const btVector3& origin = transform.getOrigin();
  const btVector3& velocity = wheel_->getLinearVelocity();
  s.centre_m = Eigen::Vector3d(origin.x(), origin.y(), origin.z());
  s.velocity_m_per_s = Eigen::Vector3d(velocity.x(), velocity.y(), velocity.z());
  if (spin_free_) {
    s.spin_angle_rad = spin_angle_rad_;
    s.spin_rate_rad_per_s = wheel_->getAngularVelocity().y();
  } else {
    // Rolling without slip about the axle: angle = travel / R (see the constructor).
    s.spin_angle_rad = (origin.x() - start_x_m_) / wheel_params_.radius_m;
    s.spin_rate_rad_per_s = velocity.x() / wheel_params_.radius_m;
  }

  s.contacts = read_contacts();
  return s;
}

}  // namespace railjoint
