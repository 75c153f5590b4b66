// GlContext on OSMesa (built with RAILJOINT_WITH_OSMESA and pkg-config osmesa,
// for the header; the library is loaded when the first context is made,
// renders/shared_library.h). The renderer draws into framebuffer objects, so
// OSMesa's own colour buffer is a token 16 x 16 pixels that nothing is drawn into.

#include <GL/osmesa.h>

#include <stdexcept>
#include <vector>

#include "renders/gl_context_backends.h"
#include "renders/shared_library.h"

namespace railjoint {

namespace {

constexpr int kTokenSide_px = 16;

// The four entry points used, from Debian 12's libosmesa6 (soname 8).
struct OsmesaApi {
  SharedLibrary library{"libOSMesa.so.8", "libosmesa6"};
  decltype(&OSMesaCreateContextAttribs) create_context_attribs =
      library.function<decltype(&OSMesaCreateContextAttribs)>("OSMesaCreateContextAttribs");
  decltype(&OSMesaDestroyContext) destroy_context =
      library.function<decltype(&OSMesaDestroyContext)>("OSMesaDestroyContext");
  decltype(&OSMesaMakeCurrent) make_current = library.function<decltype(&OSMesaMakeCurrent)>("OSMesaMakeCurrent");
  decltype(&OSMesaGetProcAddress) get_proc_address =
      library.function<decltype(&OSMesaGetProcAddress)>("OSMesaGetProcAddress");
};

const OsmesaApi& osmesa() {
  static const OsmesaApi api;  // loaded by the first context; a failed load is tried again by the next
  return api;
}

class OsmesaContext final : public GlContext {
 public:
  OsmesaContext() : buffer_(kTokenSide_px * kTokenSide_px * 4) {
    const int attributes[] = {OSMESA_FORMAT,       OSMESA_RGBA,         OSMESA_DEPTH_BITS,
                              0,                   OSMESA_STENCIL_BITS, 0,
                              OSMESA_ACCUM_BITS,   0,                   OSMESA_PROFILE,
                              OSMESA_CORE_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION, 3,
                              OSMESA_CONTEXT_MINOR_VERSION, 3,          0};
    context_ = osmesa().create_context_attribs(attributes, nullptr);
    if (context_ == nullptr) throw std::runtime_error("renderer: OSMesa could not create a core-profile GL 3.3 context");
  }
  ~OsmesaContext() override { osmesa().destroy_context(context_); }

  GlBackend backend() const override { return GlBackend::osmesa; }
  void make_current() override {
    if (osmesa().make_current(context_, buffer_.data(), GL_UNSIGNED_BYTE, kTokenSide_px, kTokenSide_px) != GL_TRUE) {
      throw std::runtime_error("renderer: OSMesaMakeCurrent failed");
    }
  }
  void release() override { osmesa().make_current(nullptr, nullptr, 0, 0, 0); }
  void* proc_address(const char* name) const override {
    return reinterpret_cast<void*>(osmesa().get_proc_address(name));
  }

 private:
  OSMesaContext context_ = nullptr;
  std::vector<unsigned char> buffer_;
};

}  // namespace

std::unique_ptr<GlContext> create_osmesa_context() { return std::make_unique<OsmesaContext>(); }

}  // namespace railjoint
