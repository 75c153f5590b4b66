#include "renders/gl_backend.h"

#include <cstdlib>
#include <stdexcept>

namespace railjoint {

const char* to_string(GlBackend backend) { return backend == GlBackend::egl ? "egl" : "osmesa"; }

bool gl_backend_built(GlBackend backend) {
  // Set by renders/CMakeLists.txt from what was found.
  return backend == GlBackend::egl ? RAILJOINT_BUILT_EGL != 0 : RAILJOINT_BUILT_OSMESA != 0;
}

std::optional<GlBackend> parse_gl_backend(const std::string& name) {
  if (name == "osmesa") return GlBackend::osmesa;
  if (name == "egl") return GlBackend::egl;
  return std::nullopt;
}

bool gl_backend_named_in_environment() {
  const char* value = std::getenv("RAILJOINT_GL");
  return value != nullptr && *value != '\0';
}

GlBackend gl_backend_from_environment() {
  if (!gl_backend_named_in_environment()) {
    if (gl_backend_built(GlBackend::osmesa)) return GlBackend::osmesa;
    if (gl_backend_built(GlBackend::egl)) return GlBackend::egl;
    throw std::runtime_error(
        "rendering unavailable: built without OSMesa or EGL (install libosmesa6-dev or libegl-dev and configure "
        "with -DRAILJOINT_WITH_OSMESA=ON or -DRAILJOINT_WITH_EGL=ON)");
  }
  const std::string name = std::getenv("RAILJOINT_GL");
  const std::optional<GlBackend> backend = parse_gl_backend(name);
  if (!backend) {
    throw std::invalid_argument("RAILJOINT_GL must be \"osmesa\" or \"egl\" (or unset: OSMesa), got \"" + name + "\"");
  }
  if (!gl_backend_built(*backend)) {
    throw std::runtime_error(std::string("rendering unavailable: RAILJOINT_GL=") + name + ", but this build has no " +
                             (*backend == GlBackend::egl ? "EGL (install libegl-dev, configure with -DRAILJOINT_WITH_EGL=ON)"
                                                         : "OSMesa (install libosmesa6-dev, configure with "
                                                           "-DRAILJOINT_WITH_OSMESA=ON)"));
  }
  return *backend;
}

}  // namespace railjoint
