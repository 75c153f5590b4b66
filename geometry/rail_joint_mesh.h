#pragma once
// Closed solids of the two rail heads at a joint (inclined dipped joint of
// thesis section 3.3, or the step joint of section 3.2.2), as coarse as the
// geometry allows: each rail end is the prism between z = -depth and its top
// over a quadrilateral footprint, 12 triangles for a planar (linear-dip or
// flat) top. Closed 2-manifold, outward winding, every triangle tagged.

#include "geometry/triangle_mesh.h"
#include "models/parameters.h"

namespace railjoint {

struct RailJointMesh {
  TriangleMesh incoming;  ///< rail the wheel starts on: -L/2 <= x <= cut_x_m(joint, y, 0)
  TriangleMesh outgoing;  ///< cut_x_m(joint, y, 1) <= x <= L/2
};

/// Choices of the mesh that are not part of the kinematic model's joint.
struct RailJointMeshOptions {
  /// Level rail ahead of the dip [m]. The linear dip of the model spans the
  /// whole rail length; a wheel started on it never crosses the entry kink of
  /// the V (where the incoming rail starts to fall). With a flat approach the
  /// incoming rail runs level at the height of its start, z = tan(beta/2) L/2,
  /// for this length before x = -L/2, one solid with a convex kink at x = -L/2.
  /// 0 = none (the kinematic model's rail). Step joints are flat anyway.
  double flat_approach_m = 0.0;
};

/// Builds both rail ends; dispatches on joint.kind. Call check_joint_geometry first.
RailJointMesh build_rail_joint_mesh(const JointParams& joint);
/// Same, with a flat approach: the incoming rail starts at
/// x = -L/2 - options.flat_approach_m (20 triangles instead of 12 for a
/// linear dip); flat_approach_m = 0 gives exactly build_rail_joint_mesh(joint).
/// Throws InputError("sim.flat_approach") for a negative or non-finite length.
RailJointMesh build_rail_joint_mesh(const JointParams& joint, const RailJointMeshOptions& options);

/// Height of the flat approach's top [m]: the incoming rail's top at x = -L/2.
double flat_approach_height_m(const JointParams& joint);

/// Throws InputError naming the key ("joint.length", "joint.gap",
/// "joint.depth", ...) and the allowed range when the joint cannot be built or
/// cannot carry the wheel across it: check_parameters with a run-up of 0.05 m
/// (the wheel starts on the slope with 50 mm to go before the cut and ends at
/// least 50 mm past its contact on the far rail), and a depth that puts the
/// bottom z = -depth below the lowest point of the rail tops.
void check_joint_geometry(const JointParams& joint, const WheelParams& wheel);

/// The shortest joint.length check_joint_geometry accepts for this joint and
/// wheel (the model's extent with the simulation's run-up) [m].
double minimum_rail_length_m(const JointParams& joint, const WheelParams& wheel);

}  // namespace railjoint
