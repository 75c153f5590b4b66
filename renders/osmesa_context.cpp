// GlContext on OSMesa (built with RAILJOINT_WITH_OSMESA and pkg-config osmesa).
// The renderer draws into framebuffer objects, so OSMesa's own colour buffer
// is a token 16 x 16 pixels that nothing is drawn into.

#include <GL/osmesa.h>

#include <stdexcept>
#include <vector>

#include "renders/gl_context_backends.h"

namespace railjoint {

namespace {

constexpr int kTokenSide_px = 16;

class OsmesaContext final : public GlContext {
 public:
  OsmesaContext() : buffer_(kTokenSide_px * kTokenSide_px * 4) {
    const int attributes[] = {OSMESA_FORMAT,       OSMESA_RGBA,         OSMESA_DEPTH_BITS,
                              0,                   OSMESA_STENCIL_BITS, 0,
                              OSMESA_ACCUM_BITS,   0,                   OSMESA_PROFILE,
                              OSMESA_CORE_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION, 3,
                              OSMESA_CONTEXT_MINOR_VERSION, 3,          0};
    context_ = OSMesaCreateContextAttribs(attributes, nullptr);
    if (context_ == nullptr) throw std::runtime_error("renderer: OSMesa could not create a core-profile GL 3.3 context");
  }
  ~OsmesaContext() override { OSMesaDestroyContext(context_); }

  GlBackend backend() const override { return GlBackend::osmesa; }
  void make_current() override {
    if (OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, kTokenSide_px, kTokenSide_px) != GL_TRUE) {
      throw std::runtime_error("renderer: OSMesaMakeCurrent failed");
    }
  }
  void release() override { OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0); }
  void* proc_address(const char* name) const override {
    return reinterpret_cast<void*>(OSMesaGetProcAddress(name));
  }

 private:
  OSMesaContext context_ = nullptr;
  std::vector<unsigned char> buffer_;
};

}  // namespace

std::unique_ptr<GlContext> create_osmesa_context() { return std::make_unique<OsmesaContext>(); }

}  // namespace railjoint
