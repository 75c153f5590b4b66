#pragma once
// The side view is a section through the wheel: only the part of the rails
// between the planes y = y_min and y = y_max (the wheel's own width) is
// drawn, closed by the section faces on those planes. Looking along y, the
// full rails would hide the wheel behind the rail in front of it (y < y_w)
// and show rail behind it (y > y_w) through its outline, so the drawn wheel
// would seem to sink into the rails where it does not touch them. In the
// section, a wheel that touches the rails without overlapping them is drawn
// touching without overlapping.

#include "geometry/triangle_mesh.h"

namespace railjoint {

/// The part of the closed CONVEX solid `solid` (outward winding) with
/// y_min_m <= y <= y_max_m, as a closed triangle soup (every triangle has its
/// own three vertices) with outward winding. Clipped triangles keep their
/// tags; the section faces on the two planes are tagged FaceTag::side (they
/// face -y / +y, as the rail-head sides do). Empty when the slab misses the
/// solid. Convexity is what makes each section a single convex polygon: a
/// non-convex solid, or y_max_m < y_min_m, throws std::invalid_argument.
/// Rail solids of a linear dip, a step or a flat approach are convex.
TriangleMesh cut_convex_solid_to_slab(const TriangleMesh& solid, double y_min_m, double y_max_m);

}  // namespace railjoint
