#pragma once
// An off-screen GL context (renders/gl_context.h: OSMesa) and the few
// things the crossing renderer draws with it: lit triangle meshes, line
// strips, round point markers drawn on top, each in one or more viewports
// (the picture and its insets), and a 2-D overlay in pixel coordinates.
// Everything is drawn into framebuffer objects of the renderer's own
// (anti-aliased by multisampling or a post-process, or not) and read back.
// No GL type appears here, so callers compile whether or not the project was
// built with a back end; without one the constructor throws
// "rendering unavailable: built without OSMesa".

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "renders/overlay_vertex.h"
#include "renders/read_back_frame.h"
#include "renders/render_settings.h"
#include "renders/rgb_image.h"

namespace railjoint {

/// True when this build can create an off-screen context (OSMesa).
bool rendering_available();

struct MeshVertex {
  Eigen::Vector3f position_m;
  Eigen::Vector3f normal;  ///< face or smooth normal; the shader turns it towards the viewer, so winding does not matter
  Eigen::Vector3f colour;  ///< linear RGB in [0, 1]
};

struct LineVertex {
  Eigen::Vector3f position_m;
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
  float specular = 0.0f;  ///< strength of a white highlight of the key light (0 = matte)
  /// Skip triangles facing away from the camera: only for closed solids with
  /// outward winding under a model map that keeps orientation (det > 0);
  /// halves the pixels a solid costs.
  bool cull_back_faces = false;
  /// < 1: blended over what is behind it, without hiding what is drawn after
  /// it (drawn after the opaque meshes of its scene, in list order).
  float opacity = 1.0f;
};

/// A rectangle of the image in pixels, origin at the top-left corner, y down.
struct PixelRect {
  int x = 0, y = 0, width = 0, height = 0;
};

/// One camera's picture: meshes (depth tested), line strips (depth tested),
/// then markers (on top of this scene).
struct SceneDraw {
  Eigen::Matrix4f view = Eigen::Matrix4f::Identity();
  Eigen::Matrix4f projection = Eigen::Matrix4f::Identity();
  bool orthographic = true;
  Eigen::Vector3f eye_m = Eigen::Vector3f::Zero();          ///< camera position (perspective lighting)
  Eigen::Vector3f to_viewer = Eigen::Vector3f::UnitZ();     ///< unit vector towards the viewer (orthographic)
  Eigen::Vector3f to_light = Eigen::Vector3f(0.0f, 0.0f, 1.0f);  ///< unit vector towards the key light
  Eigen::Vector3f background = Eigen::Vector3f::Ones();
  /// Where in the image; absent = the whole image. Each scene clears its own
  /// rectangle to `background` and has its own depth.
  std::optional<PixelRect> viewport;
  std::vector<MeshDraw> meshes;
  std::vector<MeshDraw> line_strips;
  std::vector<PointMarker> markers;
};

/// Everything one frame draws, in drawing order: the scenes, then the
/// overlay triangles (on top of all of them).
struct FrameDrawList {
  Eigen::Vector3f background = Eigen::Vector3f::Ones();  ///< behind everything (what no scene covers)
  std::vector<SceneDraw> scenes;
  std::vector<OverlayVertex> overlay;  ///< triangles
};

class OffscreenRenderer {
 public:
  /// Creates a core-profile GL 3.3 (or newer) context and
  /// framebuffers of the image size with a 24-bit depth buffer for the
  /// chosen anti-aliasing (msaa: 4 samples a pixel, or as many as the
  /// context offers). Throws std::runtime_error when OSMesa refuses.
  OffscreenRenderer(int width_px, int height_px, Antialiasing antialiasing);
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
  /// Replaces the triangles of a mesh (one that changes from frame to frame).
  void update_triangles(MeshHandle mesh, const std::vector<MeshVertex>& vertices);

  /// Draws one frame, the picture and the labels apart, and reads both back
  /// as GL hands them over; finish_frame() (renders/read_back_frame.h) makes
  /// the picture.
  void draw(const FrameDrawList& frame, ReadBackFrame& out);
  /// Draws one frame and finishes it into `out` (resized as needed, rows top first).
  void draw(const FrameDrawList& frame, RgbImage& out);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace railjoint
