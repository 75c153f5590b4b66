#include "renders/gl_functions.h"

#include <stdexcept>
#include <string>

#include "renders/gl_context.h"

namespace railjoint {

GlFunctions load_gl_functions(const GlContext& context) {
  GlFunctions gl;
#define RAILJOINT_GL_LOAD(type, name)                                                                     \
  gl.name = reinterpret_cast<type>(context.proc_address("gl" #name));                                     \
  if (gl.name == nullptr) {                                                                               \
    throw std::runtime_error("renderer: the OSMesa context has no gl" #name);                             \
  }
  RAILJOINT_GL_FUNCTIONS(RAILJOINT_GL_LOAD)
#undef RAILJOINT_GL_LOAD
  return gl;
}

}  // namespace railjoint
