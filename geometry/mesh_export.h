#pragma once
// Writing meshes to files through assimp, in metres, one named mesh (and
// scene node) per entry. Vertices are stored as float (assimp's ai_real): about
// 1e-7 relative, 0.03 um on a 0.5 m rail. No normals are written: the solids
// are faceted, and viewers derive flat normals themselves.

#include <string>
#include <utility>
#include <vector>

#include "geometry/triangle_mesh.h"

namespace railjoint {

struct MeshExportFormat {
  std::string assimp_id;    ///< e.g. "glb2"
  std::string description;  ///< e.g. "GL Transmission Format v. 2 (binary)"
};

/// The format for a file name, chosen by its extension (case-insensitive):
/// .obj Wavefront OBJ (plus a .mtl beside it), .ply binary PLY, .stl binary
/// STL, .glb binary glTF 2.0, .gltf glTF 2.0 (plus a .bin), or any other
/// extension assimp exports. PLY and STL hold a single mesh: the meshes are
/// merged and their names lost. Throws std::runtime_error naming the path and
/// the supported extensions otherwise.
MeshExportFormat mesh_export_format(const std::string& path);

/// Whether this executable writes mesh files: false where it links no assimp
/// (mesh_export_unavailable.cpp; railjoint hands `mesh` and `render` to
/// railjoint-assimp), whose functions here then throw saying so.
bool mesh_export_built();
/// Throws std::runtime_error saying which executable writes mesh files when
/// this one does not (a missing install, not bad input); else nothing.
void require_mesh_export();

/// Writes the meshes to `path` in the format of mesh_export_format(path).
/// Throws std::runtime_error with the path and the reason (assimp's, or the
/// system's for a write that failed, e.g. "No space left on device") if it cannot.
void export_meshes(const std::vector<std::pair<std::string, TriangleMesh>>& named_meshes, const std::string& path);

}  // namespace railjoint
