#pragma once
// A rail as the wheel's exact narrow phase sees it. Its triangles are exact
// where the rail top is planar, the thesis's geometry (flat head, linear dip;
// sim/cylinder_rail_contact.h, for the cylinder the wheel then is). A crowned
// head, a curved dip or a conical tread has no planar facets that would keep
// the contact where it is: there the rail also carries its analytic top, and
// the contact is the general kinematic model's (models/wheel_rail_envelope.h):
// the slice that holds the wheel up, its touching point, and the normal from
// that point to the axle in the slice's plane. The wheel only translates (and
// spins about its axle), so this is its exact contact; the geometry is the
// model's own, checked against an independent reference in the tests.

#include <optional>
#include <utility>

#include "geometry/triangle_mesh.h"
#include "models/parameters.h"
#include "sim/sim_settings.h"
#include "sim/cylinder_rail_contact.h"

namespace railjoint {

/// The analytic top of rail 0 (incoming) or 1 (outgoing), and the wheel on
/// it as simulated (a thin disc as a disc); only its contact radius comes
/// from the Bullet cylinder each step (it translates in x and z only).
struct AnalyticRailTop {
  JointParams joint;
  WheelParams wheel;
  int rail = 0;
};

struct RailSurface {
  RailSurface(TriangleMesh mesh_in) : mesh(std::move(mesh_in)) {}  // NOLINT: a mesh is a planar rail
  RailSurface(TriangleMesh mesh_in, AnalyticRailTop top) : mesh(std::move(mesh_in)), analytic_top(std::move(top)) {}
  TriangleMesh mesh;                           ///< what Bullet's broadphase and the renderer see
  std::optional<AnalyticRailTop> analytic_top; ///< set where the top is not planar or the wheel a cone
};

/// Whether the narrow phase needs the analytic top: anything but the
/// thesis's flat head, cylinder and linear dip.
bool needs_analytic_rail_top(const JointParams& joint, const WheelParams& wheel);

/// Whether a run steps on the analytic tops: where it needs them, and for a
/// thin disc over an end-post gap in kinematic mode with the exact narrow
/// phase, which then takes the disc as a disc. On the meshes the disc's 1 mm
/// stand-in narrows the gap by its width times cot(theta): a disc that drops
/// into a 20 mm gap struck 4.3 % softer (fig.-4.5 joint).
bool runs_on_analytic_rail_tops(const JointParams& joint, const WheelParams& wheel, const SimSettings& settings);

/// The nearest point of the rail within max_distance_m (found = false if none).
CylinderContact wheel_rail_contact(const WheelCylinder& wheel, const RailSurface& rail, double max_distance_m);

}  // namespace railjoint
