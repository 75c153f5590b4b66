// GlContext on EGL's surfaceless platform (built with RAILJOINT_WITH_EGL and
// pkg-config egl): no window system and no device node, Mesa's llvmpipe when
// there is no GPU. A configless (EGL_KHR_no_config_context), surfaceless
// (EGL_KHR_surfaceless_context) core-profile context: the renderer draws into
// framebuffer objects of its own. libEGL is loaded when the first context is
// made (renders/shared_library.h), not linked.

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdio>
#include <stdexcept>
#include <string>

#include "renders/gl_context_backends.h"
#include "renders/shared_library.h"

namespace railjoint {

namespace {

// The entry points used, from Debian 12's libegl1 (GLVND, soname 1).
struct EglApi {
  SharedLibrary library{"libEGL.so.1", "libegl1 and libegl-mesa0"};
#define RAILJOINT_EGL_FUNCTION(name) decltype(&::name) name = library.function<decltype(&::name)>(#name)
  RAILJOINT_EGL_FUNCTION(eglBindAPI);
  RAILJOINT_EGL_FUNCTION(eglCreateContext);
  RAILJOINT_EGL_FUNCTION(eglDestroyContext);
  RAILJOINT_EGL_FUNCTION(eglGetError);
  RAILJOINT_EGL_FUNCTION(eglGetProcAddress);
  RAILJOINT_EGL_FUNCTION(eglInitialize);
  RAILJOINT_EGL_FUNCTION(eglMakeCurrent);
  RAILJOINT_EGL_FUNCTION(eglQueryString);
#undef RAILJOINT_EGL_FUNCTION
};

const EglApi& egl() {
  static const EglApi api;  // loaded by the first context; a failed load is tried again by the next
  return api;
}

std::string egl_error(const char* what) {
  char code[16];
  std::snprintf(code, sizeof code, "0x%04X", static_cast<unsigned>(egl().eglGetError()));
  return std::string("renderer: EGL ") + what + " failed (error " + code + ")";
}

bool has_extension(const char* list, const std::string& name) {
  if (list == nullptr) return false;
  const std::string all = std::string(" ") + list + " ";
  return all.find(" " + name + " ") != std::string::npos;
}

class EglContext final : public GlContext {
 public:
  EglContext() {
    const char* client_extensions = egl().eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!has_extension(client_extensions, "EGL_MESA_platform_surfaceless")) {
      throw std::runtime_error("renderer: EGL has no surfaceless platform (EGL_MESA_platform_surfaceless); "
                               "install Mesa's EGL (libegl-mesa0)");
    }
    auto get_platform_display =
        reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(egl().eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (get_platform_display == nullptr) throw std::runtime_error("renderer: EGL has no eglGetPlatformDisplayEXT");
    display_ = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    EGLint major = 0, minor = 0;
    if (display_ == EGL_NO_DISPLAY || egl().eglInitialize(display_, &major, &minor) != EGL_TRUE) {
      throw std::runtime_error(egl_error("initialisation of the surfaceless display"));
    }
    // No eglTerminate on failure: the display is shared by every context of the process.
    {
      const char* extensions = egl().eglQueryString(display_, EGL_EXTENSIONS);
      for (const char* needed : {"EGL_KHR_no_config_context", "EGL_KHR_surfaceless_context", "EGL_KHR_create_context"}) {
        if (!has_extension(extensions, needed)) {
          throw std::runtime_error(std::string("renderer: the EGL display lacks ") + needed);
        }
      }
      if (egl().eglBindAPI(EGL_OPENGL_API) != EGL_TRUE) throw std::runtime_error(egl_error("binding desktop OpenGL"));
      const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                                   EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
      context_ = egl().eglCreateContext(display_, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
      if (context_ == EGL_NO_CONTEXT) throw std::runtime_error(egl_error("creation of a core-profile GL 3.3 context"));
    }
  }
  ~EglContext() override {
    egl().eglDestroyContext(display_, context_);
    // The display is shared by every context of the process (EGL returns the
    // same handle): terminating it would pull it from under the others.
  }

  GlBackend backend() const override { return GlBackend::egl; }
  void make_current() override {
    if (egl().eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_) != EGL_TRUE) {
      throw std::runtime_error(egl_error("eglMakeCurrent"));
    }
  }
  void release() override { egl().eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT); }
  void* proc_address(const char* name) const override { return reinterpret_cast<void*>(egl().eglGetProcAddress(name)); }

 private:
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
};

}  // namespace

std::unique_ptr<GlContext> create_egl_context() { return std::make_unique<EglContext>(); }

}  // namespace railjoint
