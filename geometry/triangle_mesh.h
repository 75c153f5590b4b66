#pragma once
// An indexed triangle mesh in metres with one tag per triangle, the common
// currency of the geometry module (the simulation, the renderer and the
// exporter all read it).

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace railjoint {

/// Which face of a solid a triangle belongs to (colouring, contact bookkeeping).
enum class FaceTag : std::uint8_t {
  top,         ///< rail top, the running surface
  cut,         ///< rail end face at the joint cut
  side,        ///< rail-head side, y = +-b_t
  end,         ///< far end of a rail piece, x = +-L/2
  bottom,      ///< z = -depth
  wheel_rim,   ///< wheel tread (cylinder)
  wheel_face,  ///< wheel side disc
};

struct TriangleMesh {
  std::vector<Eigen::Vector3d> vertices_m;  ///< [m]
  std::vector<Eigen::Vector3i> triangles;   ///< vertex indices, counter-clockwise seen from outside (outward normals)
  std::vector<FaceTag> tags;                ///< one per triangle
};

/// Enclosed volume by the divergence theorem, sum of a.(b x c)/6 [m^3]:
/// positive for a closed mesh with outward normals.
double signed_volume_m3(const TriangleMesh& mesh);

/// Sum of the triangles' areas [m^2].
double surface_area_m2(const TriangleMesh& mesh);

}  // namespace railjoint
