#pragma once
// Bullet's collision pipeline with an exact narrow phase for the wheel
// (btCylinderShape, axle along y) against a rail (btBvhTriangleMeshShape):
// registered with the dispatcher for that pair of shape types, as MuJoCo and
// Box2D keep an analytic function per shape pair. Each step it puts the one
// nearest wheel-rail point (sim/cylinder_rail_contact.h) into the pair's
// manifold; Bullet's solver resolves it as any contact. The rail's collision
// object carries its TriangleMesh as user pointer.

class btCollisionDispatcher;

namespace railjoint {

/// Registers the exact wheel-rail algorithm for both orders of the pair on
/// `dispatcher`. The create function must outlive the dispatcher's use.
class ExactWheelRailRegistration {
 public:
  explicit ExactWheelRailRegistration(btCollisionDispatcher& dispatcher);
  ~ExactWheelRailRegistration();
  ExactWheelRailRegistration(const ExactWheelRailRegistration&) = delete;
  ExactWheelRailRegistration& operator=(const ExactWheelRailRegistration&) = delete;

 private:
  struct CreateFunctions;
  CreateFunctions* functions_;
};

}  // namespace railjoint
