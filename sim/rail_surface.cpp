#include "sim/rail_surface.h"

#include <cmath>

#include "models/wheel_rail_envelope.h"

namespace railjoint {

bool needs_analytic_rail_top(const JointParams& joint, const WheelParams& wheel) {
  return !has_thesis_geometry(joint, wheel);
}

bool runs_on_analytic_rail_tops(const JointParams& joint, const WheelParams& wheel, const SimSettings& settings) {
  if (needs_analytic_rail_top(joint, wheel)) return true;
  return wheel.width_m == 0.0 && joint.gap_m > 0.0 && settings.mode() == SimMode::kinematic &&
         settings.narrow_phase == NarrowPhase::exact;
}

namespace {
CylinderContact analytic_contact(const WheelCylinder& cylinder, const AnalyticRailTop& top, double max_distance_m) {
  // The tread as simulated: the model's wheel (a thin disc as a disc, its
  // width and lateral position, its conicity) with the contact radius
  // (Bullet's R + slop + margin convention, cylinder_rail_contact.h).
  WheelParams wheel = top.wheel;
  wheel.radius_m = cylinder.radius_m;
  const RailSupport support = rail_support(top.joint, wheel, top.rail, cylinder.centre_m.x());
  CylinderContact contact;
  if (!std::isfinite(support.centre_z_m)) return contact;
  // The normal at the touching configuration, from the rail point to the
  // axle in the slice's plane; the signed distance along it to first order
  // in the height above that configuration (exact on a face, O(d^2 / R) on
  // an edge: 1e-18 m at the 1e-9 m the solver leaves).
  const double nx = cylinder.centre_m.x() - support.contact_m.x();
  const double nz = support.centre_z_m - support.contact_m.z();
  const double length = std::hypot(nx, nz);
  if (!(length > 0.0)) return contact;
  contact.normal = Eigen::Vector3d(nx / length, 0.0, nz / length);
  contact.distance_m = (cylinder.centre_m.z() - support.centre_z_m) * contact.normal.z();
  if (!(contact.distance_m <= max_distance_m)) return CylinderContact{};
  contact.found = true;
  contact.point_on_rail_m = support.contact_m;
  contact.at_edge = support.at_cut_edge;
  return contact;
}
}  // namespace

CylinderContact wheel_rail_contact(const WheelCylinder& wheel, const RailSurface& rail, double max_distance_m) {
  if (rail.analytic_top) return analytic_contact(wheel, *rail.analytic_top, max_distance_m);
  return cylinder_rail_contact(wheel, rail.mesh, max_distance_m);
}

}  // namespace railjoint
