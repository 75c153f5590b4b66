#pragma once
// A tagged mesh split into one mesh per face tag (top, cut, side, end,
// bottom, wheel rim and faces), so that files written for other tools keep
// the faces apart: a viewer or a contact code can pick the running surface
// or the cut face by name.

#include <utility>
#include <vector>

#include "geometry/triangle_mesh.h"

namespace railjoint {

/// "top", "cut", "side", "end", "bottom"; the wheel's "rim" and "face".
const char* to_string(FaceTag tag);

/// One mesh per tag that occurs, in FaceTag order, each holding only the
/// vertices its triangles use (winding and coordinates unchanged). Together
/// they hold every triangle once, so their signed volumes add up to the
/// original's; each alone is an open surface.
std::vector<std::pair<FaceTag, TriangleMesh>> split_by_face_tag(const TriangleMesh& mesh);

}  // namespace railjoint
