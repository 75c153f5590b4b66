// OffscreenRenderer for a build without OSMesa: everything that
// mentions the renderer still compiles and links, and using it says why it
// cannot work.

#include <stdexcept>

#include "renders/offscreen_renderer.h"

namespace railjoint {

namespace {
[[noreturn]] void unavailable() {
  throw std::runtime_error(
      "rendering unavailable: built without OSMesa (install libosmesa6-dev and configure with "
      "-DRAILJOINT_WITH_OSMESA=ON)");
}
}  // namespace

bool rendering_available() { return false; }

struct OffscreenRenderer::Impl {};

OffscreenRenderer::OffscreenRenderer(int, int, Antialiasing) { unavailable(); }
OffscreenRenderer::~OffscreenRenderer() = default;
const std::string& OffscreenRenderer::gl_version() const { unavailable(); }
const std::string& OffscreenRenderer::gl_renderer() const { unavailable(); }
MeshHandle OffscreenRenderer::add_triangles(const std::vector<MeshVertex>&) { unavailable(); }
MeshHandle OffscreenRenderer::add_line_strip(const std::vector<LineVertex>&) { unavailable(); }
void OffscreenRenderer::update_triangles(MeshHandle, const std::vector<MeshVertex>&) { unavailable(); }
void OffscreenRenderer::draw(const FrameDrawList&, ReadBackFrame&) { unavailable(); }
void OffscreenRenderer::draw(const FrameDrawList&, RgbImage&) { unavailable(); }

}  // namespace railjoint
