#include "renders/gl_context.h"

#include <stdexcept>

#include "renders/gl_context_backends.h"

namespace railjoint {

std::unique_ptr<GlContext> create_gl_context(GlBackend backend) {
  if (!gl_backend_built(backend)) {
    throw std::runtime_error(std::string("rendering unavailable: this build has no ") +
                             (backend == GlBackend::egl ? "EGL" : "OSMesa"));
  }
#if RAILJOINT_BUILT_OSMESA
  if (backend == GlBackend::osmesa) return create_osmesa_context();
#endif
#if RAILJOINT_BUILT_EGL
  if (backend == GlBackend::egl) return create_egl_context();
#endif
  throw std::logic_error("create_gl_context: back end built but not linked");
}

}  // namespace railjoint
