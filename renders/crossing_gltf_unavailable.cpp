// crossing_gltf.h in an executable that links no assimp (geometry/CMakeLists.txt
// says why): railjoint hands `render` and `simulate --render-out` to
// railjoint-assimp (scenes/cli/main.cpp), so this runs only when that one is missing.

#include <stdexcept>

#include "renders/crossing_gltf.h"

namespace railjoint {

GltfReport write_crossing_gltf(const std::filesystem::path& path, const RenderSettings& /*settings*/,
                               const RailJointMesh& /*rails*/, const TriangleMesh& /*wheel*/,
                               const Trajectory& /*trajectory*/) {
  throw std::runtime_error(path.string() +
                           ": the glTF is written by railjoint-assimp, the executable beside "
                           "railjoint that links assimp, and it is not there: build or install "
                           "railjoint again");
}

}  // namespace railjoint
