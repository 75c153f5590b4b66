#pragma once
// Exact contact between the wheel, a cylinder whose axle is the world y axis,
// and a rail: a closed triangle mesh with outward normals. Bullet's generic
// narrow phase (GJK / EPA on a 0.475 m cylinder) gave normals off by ~1.5e-4
// rad at the struck edge, a noise of ~1e-3 of a scenario-2 jump in every step
// (sim/DESIGN.md "How the error floor was removed"); this one is exact
// to round-off and is handed to Bullet's solver as the wheel-rail contact
// (sim/exact_wheel_rail_algorithm.h). Pure geometry, Eigen only.
//
// Why the wheel's contact reduces to a few closed forms: the wheel only
// translates (and spins about its own axle, which does not move its surface),
// so its distance to a rail point p inside its lateral span is
// rho(p) - r, rho the distance from p to the axle in the x-z plane. The
// nearest rail point is then either
//  - the foot of the axle on a face that contains the y direction (a rail top
//    z = m x + c), if the face reaches the foot within the span: distance
//    s - r, s the centre's height above the face's plane, normal the face's;
//  - or the point of an edge (clipped to the span) nearest the axle, where
//    rho^2 is a quadratic in the edge parameter: distance rho - r, normal
//    from the point to the axle. The cut edge and the step edge are met this
//    way; edges inside a flat face never win over its foot, so the mesh's
//    diagonals need no special treatment.
// Faces that do not contain y (the cut face, the rail's sides) can only be
// nearest through their edges while the axle does not pierce them.

#include <limits>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "geometry/triangle_mesh.h"

namespace railjoint {

struct WheelCylinder {
  Eigen::Vector3d centre_m = Eigen::Vector3d::Zero();
  double radius_m = 0.475;      ///< contact radius (Bullet's: R + slop) [m]
  double half_width_m = 5e-4;   ///< half the extent along y [m]
};

struct CylinderContact {
  bool found = false;
  double distance_m = std::numeric_limits<double>::infinity();  ///< signed gap, < 0 overlap [m]
  Eigen::Vector3d point_on_rail_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  ///< unit, from the rail into the wheel (y component 0)
  bool at_edge = false;  ///< on the analytic tops: the contact sits on the rail end's edge at the cut
};

/// The nearest point of one triangle (a, b, c counter-clockwise from outside).
CylinderContact cylinder_triangle_contact(const WheelCylinder& wheel, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                          const Eigen::Vector3d& c);

/// The nearest point of a rail mesh within max_distance_m (found = false if none).
CylinderContact cylinder_rail_contact(const WheelCylinder& wheel, const TriangleMesh& rail, double max_distance_m);

}  // namespace railjoint
