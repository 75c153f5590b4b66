#include "renders/gl_context.h"

#include <GL/osmesa.h>
#include <dlfcn.h>

#include <stdexcept>
#include <string>

namespace railjoint {

namespace {

constexpr int kTokenSide_px = 16;

void* osmesa_symbol(void* library, const char* name) {
  void* address = dlsym(library, name);
  if (address == nullptr) throw std::runtime_error(std::string("renderer: libOSMesa.so.8 has no ") + name);
  return address;
}

// The four entry points used, from Debian 12's libosmesa6 (soname 8).
struct Osmesa {
  void* library = dlopen("libOSMesa.so.8", RTLD_NOW | RTLD_LOCAL);
  decltype(&OSMesaCreateContextAttribs) create_context_attribs = nullptr;
  decltype(&OSMesaDestroyContext) destroy_context = nullptr;
  decltype(&OSMesaMakeCurrent) make_current = nullptr;
  decltype(&OSMesaGetProcAddress) get_proc_address = nullptr;

  Osmesa() {
    if (library == nullptr) {
      const char* reason = dlerror();
      throw std::runtime_error(std::string("renderer: cannot load libOSMesa.so.8 (") + (reason ? reason : "unknown") +
                               "); install Debian's libosmesa6");
    }
    create_context_attribs = reinterpret_cast<decltype(create_context_attribs)>(
        osmesa_symbol(library, "OSMesaCreateContextAttribs"));
    destroy_context = reinterpret_cast<decltype(destroy_context)>(osmesa_symbol(library, "OSMesaDestroyContext"));
    make_current = reinterpret_cast<decltype(make_current)>(osmesa_symbol(library, "OSMesaMakeCurrent"));
    get_proc_address = reinterpret_cast<decltype(get_proc_address)>(osmesa_symbol(library, "OSMesaGetProcAddress"));
  }
};

const Osmesa& osmesa() {
  static const Osmesa api;  // loaded by the first context; a failed load is tried again by the next
  return api;
}

OSMesaContext as_osmesa(void* context) { return static_cast<OSMesaContext>(context); }

}  // namespace

// The framebuffer objects carry their own depth buffer, so OSMesa's gets none.
GlContext::GlContext() : token_buffer_(kTokenSide_px * kTokenSide_px * 4) {
  const int attributes[] = {OSMESA_FORMAT,        OSMESA_RGBA, OSMESA_DEPTH_BITS, 0, OSMESA_STENCIL_BITS, 0,
                            OSMESA_ACCUM_BITS,    0,           OSMESA_PROFILE,    OSMESA_CORE_PROFILE,
                            OSMESA_CONTEXT_MAJOR_VERSION, 3,   OSMESA_CONTEXT_MINOR_VERSION, 3, 0};
  context_ = osmesa().create_context_attribs(attributes, nullptr);
  if (context_ == nullptr) throw std::runtime_error("renderer: OSMesa could not create a core-profile GL 3.3 context");
}

GlContext::~GlContext() { osmesa().destroy_context(as_osmesa(context_)); }

void GlContext::make_current() {
  if (osmesa().make_current(as_osmesa(context_), token_buffer_.data(), GL_UNSIGNED_BYTE, kTokenSide_px,
                            kTokenSide_px) != GL_TRUE) {
    throw std::runtime_error("renderer: OSMesaMakeCurrent failed");
  }
}

void GlContext::release() { osmesa().make_current(nullptr, nullptr, 0, 0, 0); }

GlFunctions GlContext::load_functions() const {
  GlFunctions gl;
#define RAILJOINT_GL_LOAD(name)                                                               \
  gl.name = reinterpret_cast<decltype(gl.name)>(osmesa().get_proc_address("gl" #name));             \
  if (gl.name == nullptr) throw std::runtime_error("renderer: the OSMesa context has no gl" #name);
  RAILJOINT_GL_FUNCTIONS(RAILJOINT_GL_LOAD)
#undef RAILJOINT_GL_LOAD
  return gl;
}

}  // namespace railjoint
