#pragma once
// One body of the force run (elastic_crossing_run.h): Bullet integrates it;
// it moves along z only (the wheel's horizontal speed is set by the carrier
// every step) and is paired with nothing, so Bullet finds no contacts and
// solves none.

#include <memory>

#include <btBulletDynamicsCommon.h>

namespace railjoint {

struct VerticalBody {
  std::unique_ptr<btCollisionShape> shape;
  std::unique_ptr<btRigidBody> body;

  VerticalBody(btDiscreteDynamicsWorld& world, std::unique_ptr<btCollisionShape> body_shape, double mass_kg,
               const btVector3& position_m, const btVector3& velocity_m_per_s)
      : shape(std::move(body_shape)) {
    btVector3 inertia(0, 0, 0);
    shape->calculateLocalInertia(mass_kg, inertia);
    btTransform transform;
    transform.setIdentity();
    transform.setOrigin(position_m);
    btRigidBody::btRigidBodyConstructionInfo info(mass_kg, nullptr, shape.get(), inertia);
    info.m_startWorldTransform = transform;
    info.m_linearDamping = 0.0;
    info.m_angularDamping = 0.0;
    body = std::make_unique<btRigidBody>(info);
    body->setActivationState(DISABLE_DEACTIVATION);
    body->setLinearFactor(btVector3(0, 0, 1));
    body->setAngularFactor(btVector3(0, 0, 0));
    world.addRigidBody(body.get(), 1, 0);  // mask 0: no broadphase pair, no Bullet contact
    body->setLinearVelocity(velocity_m_per_s);
  }
  double z_m() const { return body->getWorldTransform().getOrigin().z(); }
  double zdot_m_per_s() const { return body->getLinearVelocity().z(); }
  void push_up(double force_N) { body->applyCentralForce(btVector3(0, 0, force_N)); }
};

/// A spring and damper between a body above and one below (or the ground):
/// the force it pushes them apart with [N], from its compression [m] and the
/// compression's rate [m/s].
inline double spring_damper_N(double stiffness_N_per_m, double damping_N_s_per_m, double compression_m,
                              double compression_rate_m_per_s) {
  return stiffness_N_per_m * compression_m + damping_N_s_per_m * compression_rate_m_per_s;
}

}  // namespace railjoint
