#pragma once
// An OSMesa (software GL, no display) context and the few things the crossing
// renderer draws with it: lit triangle meshes, line strips, round point
// markers drawn on top of everything, and a 2-D overlay in pixel coordinates.
// No GL type appears here, so callers compile whether or not the project was
// built with OSMesa; without it the constructor throws
// "rendering unavailable: built without OSMesa".

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "renders/rgb_image.h"

namespace railjoint {

/// True when this build can create an OSMesa context.
bool rendering_available();

struct MeshVertex {
  Eigen::Vector3f position_m;
  Eigen::Vector3f normal;  ///< face normal; the shader turns it towards the viewer, so winding does not matter
  Eigen::Vector3f colour;  ///< linear RGB in [0, 1]
};

struct LineVertex {
  Eigen::Vector3f position_m;
  Eigen::Vector3f colour;
};

struct OverlayVertex {
  Eigen::Vector2f position_px;  ///< origin at the top-left corner, y down
  Eigen::Vector3f colour;
};

struct PointMarker {
  Eigen::Vector3f position_m;
  Eigen::Vector3f colour;
  float diameter_px = 8.0f;
  bool ring = false;  ///< draw a ring, leaving the marked spot visible
};

using MeshHandle = int;

struct MeshDraw {
  MeshHandle mesh = -1;
  Eigen::Matrix4f model = Eigen::Matrix4f::Identity();  ///< any invertible affine map (normals get its inverse transpose)
  int vertex_count = -1;                                 ///< draw the first n vertices; -1 = all
};

/// Everything one frame draws, in drawing order: meshes (depth tested), line
/// strips (depth tested), markers (on top), overlay triangles (on top).
struct FrameDrawList {
  Eigen::Matrix4f view = Eigen::Matrix4f::Identity();
  Eigen::Matrix4f projection = Eigen::Matrix4f::Identity();
  bool orthographic = true;
  Eigen::Vector3f eye_m = Eigen::Vector3f::Zero();          ///< camera position (perspective lighting)
  Eigen::Vector3f to_viewer = Eigen::Vector3f::UnitZ();     ///< unit vector towards the viewer (orthographic)
  Eigen::Vector3f to_light = Eigen::Vector3f(0.0f, 0.0f, 1.0f);  ///< unit vector towards the key light
  Eigen::Vector3f background = Eigen::Vector3f::Ones();
  std::vector<MeshDraw> meshes;
  std::vector<MeshDraw> line_strips;
  std::vector<PointMarker> markers;
  std::vector<OverlayVertex> overlay;  ///< triangles
};

class OffscreenRenderer {
 public:
  /// Creates a core-profile GL 3.3 (or newer) context with a 24-bit depth
  /// buffer. Throws std::runtime_error when OSMesa is missing or refuses.
  OffscreenRenderer(int width_px, int height_px);
  ~OffscreenRenderer();
  OffscreenRenderer(const OffscreenRenderer&) = delete;
  OffscreenRenderer& operator=(const OffscreenRenderer&) = delete;

  /// GL_VERSION and GL_RENDERER of the context actually created.
  const std::string& gl_version() const;
  const std::string& gl_renderer() const;

  /// Uploads a triangle list (3 vertices per triangle) once; draw it by handle.
  MeshHandle add_triangles(const std::vector<MeshVertex>& vertices);
  /// Uploads a line strip once (e.g. the wheel-centre path).
  MeshHandle add_line_strip(const std::vector<LineVertex>& vertices);

  /// Draws one frame and reads it back into `out` (resized as needed, rows top first).
  void draw(const FrameDrawList& frame, RgbImage& out);

  int width_px() const;
  int height_px() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace railjoint
