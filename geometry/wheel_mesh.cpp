#include "geometry/wheel_mesh.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>

namespace railjoint {

TriangleMesh build_wheel_mesh(const WheelParams& wheel, int segments, double min_width_m) {
  assert(segments >= 3);
  const double R = wheel.radius_m;  // at the wheel's centre plane, y = 0 here
  const double half_width = std::max(wheel.width_m, min_width_m) / 2.0;
  TriangleMesh mesh;
  // Ring vertex k of face j (j = 0 at y = -w/2, 1 at +w/2) has index j * segments + k;
  // the angle runs from +x towards +z.
  for (const double y : {-half_width, half_width}) {
    // A conical tread: the radius at each face, R - conicity y (wheel_tread.h).
    const double r = R - wheel.conicity * y;
    for (int k = 0; k < segments; ++k) {
      const double phi = 2.0 * std::numbers::pi * k / segments;
      mesh.vertices_m.emplace_back(r * std::cos(phi), y, r * std::sin(phi));
    }
  }
  const int centre_0 = 2 * segments;
  mesh.vertices_m.emplace_back(0.0, -half_width, 0.0);
  mesh.vertices_m.emplace_back(0.0, half_width, 0.0);

  for (int k = 0; k < segments; ++k) {
    const int next = (k + 1) % segments;
    // Tread quad, outward (radial) winding: across the width first, then along phi.
    mesh.triangles.emplace_back(k, segments + k, segments + next);
    mesh.triangles.emplace_back(k, segments + next, next);
    mesh.tags.insert(mesh.tags.end(), 2, FaceTag::wheel_rim);
    // Side discs: +phi is counter-clockwise seen from -y, clockwise from +y.
    mesh.triangles.emplace_back(centre_0, k, next);
    mesh.triangles.emplace_back(centre_0 + 1, segments + next, segments + k);
    mesh.tags.insert(mesh.tags.end(), 2, FaceTag::wheel_face);
  }
  return mesh;
}

}  // namespace railjoint
