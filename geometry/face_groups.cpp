#include "geometry/face_groups.h"

#include <array>

namespace railjoint {

namespace {
constexpr std::array kAllTags = {FaceTag::top,    FaceTag::cut,       FaceTag::side,      FaceTag::end,
                                 FaceTag::bottom, FaceTag::wheel_rim, FaceTag::wheel_face};
}  // namespace

const char* to_string(FaceTag tag) {
  switch (tag) {
    case FaceTag::top: return "top";
    case FaceTag::cut: return "cut";
    case FaceTag::side: return "side";
    case FaceTag::end: return "end";
    case FaceTag::bottom: return "bottom";
    case FaceTag::wheel_rim: return "rim";
    case FaceTag::wheel_face: return "face";
  }
  return "?";
}

std::vector<std::pair<FaceTag, TriangleMesh>> split_by_face_tag(const TriangleMesh& mesh) {
  std::vector<std::pair<FaceTag, TriangleMesh>> groups;
  for (const FaceTag tag : kAllTags) {
    TriangleMesh group;
    // New index of each original vertex in this group; -1: not used yet.
    std::vector<int> index_in_group(mesh.vertices_m.size(), -1);
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      if (mesh.tags[t] != tag) continue;
      Eigen::Vector3i triangle;
      for (int corner = 0; corner < 3; ++corner) {
        int& index = index_in_group[static_cast<std::size_t>(mesh.triangles[t][corner])];
        if (index < 0) {
          index = static_cast<int>(group.vertices_m.size());
          group.vertices_m.push_back(mesh.vertices_m[static_cast<std::size_t>(mesh.triangles[t][corner])]);
        }
        triangle[corner] = index;
      }
      group.triangles.push_back(triangle);
      group.tags.push_back(tag);
    }
    if (!group.triangles.empty()) groups.emplace_back(tag, std::move(group));
  }
  return groups;
}

}  // namespace railjoint
