#pragma once
// Render mesh of the wheel. The simulation never uses it: a tessellated wheel
// with N sides shakes its centre by slopes of order pi/N (sim/DESIGN.md
// "What the simulation must hold"), so Bullet gets an implicit cylinder.

#include "geometry/triangle_mesh.h"
#include "models/parameters.h"

namespace railjoint {

/// Closed prism over a regular `segments`-gon inscribed in radius R, axle
/// along y, centred at the origin, width max(b_w, min_width) so a thin disc
/// (b_w = 0) stays visible. Each side face is a fan around its centre vertex:
/// 2 segments + 2 vertices, 4 segments triangles (2 segments wheel_rim,
/// 2 segments wheel_face). segments >= 3.
TriangleMesh build_wheel_mesh(const WheelParams& wheel, int segments, double min_width_m = 0.01);

}  // namespace railjoint
