#include "sim/exact_wheel_rail_algorithm.h"

#include <new>

#include <btBulletCollisionCommon.h>
#include <BulletCollision/BroadphaseCollision/btCollisionAlgorithm.h>
#include <BulletCollision/CollisionDispatch/btCollisionCreateFunc.h>
#include <BulletCollision/CollisionDispatch/btCollisionObjectWrapper.h>
#include <BulletCollision/CollisionDispatch/btManifoldResult.h>

#include "sim/rail_surface.h"

namespace railjoint {

namespace {

class ExactWheelRailAlgorithm : public btCollisionAlgorithm {
 public:
  ExactWheelRailAlgorithm(const btCollisionAlgorithmConstructionInfo& info, const btCollisionObjectWrapper* body0,
                          const btCollisionObjectWrapper* body1)
      : btCollisionAlgorithm(info) {
    manifold_ = m_dispatcher->getNewManifold(body0->getCollisionObject(), body1->getCollisionObject());
  }
  ~ExactWheelRailAlgorithm() override {
    if (manifold_ != nullptr) m_dispatcher->releaseManifold(manifold_);
  }

  void processCollision(const btCollisionObjectWrapper* body0, const btCollisionObjectWrapper* body1,
                        const btDispatcherInfo& /*dispatch_info*/, btManifoldResult* result) override {
    result->setPersistentManifold(manifold_);
    const bool wheel_first = body0->getCollisionShape()->getShapeType() == CYLINDER_SHAPE_PROXYTYPE;
    const btCollisionObjectWrapper* wheel_wrap = wheel_first ? body0 : body1;
    const btCollisionObjectWrapper* rail_wrap = wheel_first ? body1 : body0;
    const auto* rail = static_cast<const RailSurface*>(rail_wrap->getCollisionObject()->getUserPointer());
    if (rail == nullptr) return;
    const auto* cylinder = static_cast<const btCylinderShape*>(wheel_wrap->getCollisionShape());
    const btVector3 half = cylinder->getHalfExtentsWithMargin();
    const btVector3& origin = wheel_wrap->getWorldTransform().getOrigin();
    WheelCylinder wheel;
    wheel.centre_m = Eigen::Vector3d(origin.x(), origin.y(), origin.z());
    // Bullet's convention, kept so both narrow phases rest the wheel alike:
    // the rail surface lies its margin above the triangles.
    wheel.radius_m = half.x() + rail_wrap->getCollisionShape()->getMargin();
    wheel.half_width_m = half.y();
    const CylinderContact contact = wheel_rail_contact(wheel, *rail, manifold_->getContactBreakingThreshold());
    if (!contact.found) return;
    const btVector3 n(contact.normal.x(), contact.normal.y(), contact.normal.z());
    const btVector3 on_rail(contact.point_on_rail_m.x(), contact.point_on_rail_m.y(), contact.point_on_rail_m.z());
    // addContactPoint takes the normal pointing from body 1 to body 0 and the point on body 1.
    if (wheel_first) {
      result->addContactPoint(n, on_rail, contact.distance_m);
    } else {
      result->addContactPoint(-n, on_rail + n * contact.distance_m, contact.distance_m);
    }
  }

  btScalar calculateTimeOfImpact(btCollisionObject*, btCollisionObject*, const btDispatcherInfo&,
                                 btManifoldResult*) override {
    return 1.0;  // no continuous collision: impacts are located by the stepping loop
  }

  void getAllContactManifolds(btManifoldArray& manifolds) override {
    if (manifold_ != nullptr) manifolds.push_back(manifold_);
  }

 private:
  btPersistentManifold* manifold_ = nullptr;
};

struct CreateExact : btCollisionAlgorithmCreateFunc {
  btCollisionAlgorithm* CreateCollisionAlgorithm(btCollisionAlgorithmConstructionInfo& info,
                                                 const btCollisionObjectWrapper* body0,
                                                 const btCollisionObjectWrapper* body1) override {
    void* memory = info.m_dispatcher1->allocateCollisionAlgorithm(sizeof(ExactWheelRailAlgorithm));
    return new (memory) ExactWheelRailAlgorithm(info, body0, body1);
  }
};

}  // namespace

struct ExactWheelRailRegistration::CreateFunctions {
  CreateExact create;
};

ExactWheelRailRegistration::ExactWheelRailRegistration(btCollisionDispatcher& dispatcher)
    : functions_(new CreateFunctions) {
  dispatcher.registerCollisionCreateFunc(CYLINDER_SHAPE_PROXYTYPE, TRIANGLE_MESH_SHAPE_PROXYTYPE, &functions_->create);
  dispatcher.registerCollisionCreateFunc(TRIANGLE_MESH_SHAPE_PROXYTYPE, CYLINDER_SHAPE_PROXYTYPE, &functions_->create);
}

ExactWheelRailRegistration::~ExactWheelRailRegistration() { delete functions_; }

}  // namespace railjoint
