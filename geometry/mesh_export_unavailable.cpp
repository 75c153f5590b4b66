// mesh_export.h in an executable that links no assimp (geometry/CMakeLists.txt):
// railjoint hands every command that writes a mesh file to railjoint-assimp
// (scenes/cli/main.cpp), so these run only when that one is missing.

#include <stdexcept>

#include "geometry/mesh_export.h"

namespace railjoint {

bool mesh_export_built() { return false; }

void require_mesh_export() {
  throw std::runtime_error(
      "mesh files are written by railjoint-assimp, the executable beside railjoint that links "
      "assimp, and it is not there: build or install railjoint again");
}

MeshExportFormat mesh_export_format(const std::string& /*path*/) {
  require_mesh_export();
  return {};
}

void export_meshes(const std::vector<std::pair<std::string, TriangleMesh>>& /*named_meshes*/,
                   const std::string& /*path*/) {
  require_mesh_export();
}

}  // namespace railjoint
