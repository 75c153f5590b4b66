#pragma once
// Invariants of a closed triangle mesh, computed here from the indices and
// positions alone (never with the code under test), for the geometry tests.

#include <Eigen/Geometry>
#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <utility>

#include "geometry/triangle_mesh.h"

namespace railjoint::test {

/// Empty if the mesh is a closed 2-manifold with consistent winding: every
/// directed edge (a, b) occurs in exactly one triangle and (b, a) in exactly
/// one other, so each undirected edge is in exactly two triangles with opposite
/// directions. Also rejects repeated vertex positions (they would hide a crack
/// behind distinct indices), degenerate triangles and unused vertices.
inline std::string manifold_defects(const TriangleMesh& mesh) {
  std::ostringstream out;
  if (mesh.tags.size() != mesh.triangles.size()) out << "tags " << mesh.tags.size() << " != triangles; ";
  std::map<std::pair<int, int>, int> directed;
  std::set<int> used;
  for (const Eigen::Vector3i& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      used.insert(t[k]);
      ++directed[{t[k], t[(k + 1) % 3]}];
    }
    const Eigen::Vector3d n =
        (mesh.vertices_m[t[1]] - mesh.vertices_m[t[0]]).cross(mesh.vertices_m[t[2]] - mesh.vertices_m[t[0]]);
    if (!(n.norm() > 1e-14)) out << "degenerate triangle " << t.transpose() << "; ";
  }
  for (const auto& [edge, count] : directed) {
    const auto reverse = directed.find({edge.second, edge.first});
    if (count != 1) out << "edge " << edge.first << "->" << edge.second << " used " << count << " times; ";
    if (reverse == directed.end() || reverse->second != 1) {
      out << "edge " << edge.first << "-" << edge.second << " has no single opposite; ";
    }
  }
  if (used.size() != mesh.vertices_m.size()) out << mesh.vertices_m.size() - used.size() << " unused vertices; ";
  for (std::size_t i = 0; i < mesh.vertices_m.size(); ++i) {
    for (std::size_t j = i + 1; j < mesh.vertices_m.size(); ++j) {
      if ((mesh.vertices_m[i] - mesh.vertices_m[j]).norm() < 1e-12)
        out << "vertices " << i << " and " << j << " coincide; ";
    }
  }
  return out.str();
}

/// Unit outward normal of triangle i (right-hand rule on its winding).
inline Eigen::Vector3d unit_normal(const TriangleMesh& mesh, std::size_t i) {
  const Eigen::Vector3i& t = mesh.triangles[i];
  return (mesh.vertices_m[t[1]] - mesh.vertices_m[t[0]])
      .cross(mesh.vertices_m[t[2]] - mesh.vertices_m[t[0]])
      .normalized();
}

struct Box {
  Eigen::Vector3d min = Eigen::Vector3d::Constant(INFINITY);
  Eigen::Vector3d max = Eigen::Vector3d::Constant(-INFINITY);
};

inline Box bounding_box(const TriangleMesh& mesh) {
  Box box;
  for (const Eigen::Vector3d& v : mesh.vertices_m) {
    box.min = box.min.cwiseMin(v);
    box.max = box.max.cwiseMax(v);
  }
  return box;
}

}  // namespace railjoint::test
