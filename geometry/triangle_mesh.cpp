#include "geometry/triangle_mesh.h"

#include <Eigen/Geometry>

namespace railjoint {

double signed_volume_m3(const TriangleMesh& mesh) {
  double six_volume = 0.0;
  for (const Eigen::Vector3i& t : mesh.triangles) {
    six_volume += mesh.vertices_m[t[0]].dot(mesh.vertices_m[t[1]].cross(mesh.vertices_m[t[2]]));
  }
  return six_volume / 6.0;
}

double surface_area_m2(const TriangleMesh& mesh) {
  double twice_area = 0.0;
  for (const Eigen::Vector3i& t : mesh.triangles) {
    const Eigen::Vector3d& a = mesh.vertices_m[t[0]];
    twice_area += (mesh.vertices_m[t[1]] - a).cross(mesh.vertices_m[t[2]] - a).norm();
  }
  return twice_area / 2.0;
}

}  // namespace railjoint
