#pragma once
// An OpenGL 3.3 core-profile context of OSMesa (Mesa's llvmpipe: no window
// system, no GPU). The renderer draws into framebuffer objects of its own,
// so OSMesa's colour buffer is a token nothing is drawn into. libOSMesa is
// loaded by the first context (dlopen) and never unloaded, and the GL entry
// points come through OSMesaGetProcAddress (renders/DESIGN.md "One back
// end"). Private to renders/; include only in files that draw.

#define GL_GLEXT_PROTOTYPES  // declares gl* for decltype only: nothing links them
#include <GL/glcorearb.h>

#include <vector>

namespace railjoint {

#define RAILJOINT_GL_FUNCTIONS(X)                                                                           \
  X(GetString) X(GetIntegerv) X(GetError) X(CreateShader) X(ShaderSource) X(CompileShader) X(GetShaderiv)   \
  X(GetShaderInfoLog) X(DeleteShader) X(CreateProgram) X(AttachShader) X(LinkProgram) X(GetProgramiv)       \
  X(GetProgramInfoLog) X(DeleteProgram) X(UseProgram) X(GetUniformLocation) X(Uniform1i) X(Uniform1f)       \
  X(Uniform2f) X(Uniform3fv) X(UniformMatrix3fv) X(UniformMatrix4fv) X(GenVertexArrays) X(BindVertexArray)  \
  X(GenBuffers) X(BindBuffer) X(BufferData) X(EnableVertexAttribArray) X(VertexAttribPointer) X(DrawArrays) \
  X(Enable) X(Disable) X(DepthFunc) X(BlendFunc) X(DepthMask) X(Viewport) X(Scissor) X(ClearColor) X(Clear) \
  X(ReadPixels) X(GenFramebuffers) X(BindFramebuffer) X(FramebufferRenderbuffer) X(CheckFramebufferStatus)  \
  X(BlitFramebuffer) X(GenRenderbuffers) X(BindRenderbuffer) X(RenderbufferStorageMultisample)

/// One pointer per entry point, named without the "gl" prefix: gl.Clear(...).
struct GlFunctions {
#define RAILJOINT_GL_MEMBER(name) decltype(&gl##name) name = nullptr;
  RAILJOINT_GL_FUNCTIONS(RAILJOINT_GL_MEMBER)
#undef RAILJOINT_GL_MEMBER
};

class GlContext {
 public:
  /// Throws std::runtime_error naming the Debian package when libOSMesa is
  /// missing, or saying that OSMesa gave no core-profile context.
  GlContext();
  ~GlContext();
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  void make_current();
  void release();
  /// Every entry point, from this context (which must be current); throws
  /// std::runtime_error naming the first one missing.
  GlFunctions load_functions() const;

 private:
  void* context_ = nullptr;  // OSMesaContext
  std::vector<unsigned char> token_buffer_;
};

/// Makes `context` current for a scope: several contexts may live in one
/// thread (tests), and none is left current for another to find.
class CurrentContext {
 public:
  explicit CurrentContext(GlContext& context) : context_(context) { context_.make_current(); }
  ~CurrentContext() { context_.release(); }
  CurrentContext(const CurrentContext&) = delete;
  CurrentContext& operator=(const CurrentContext&) = delete;

 private:
  GlContext& context_;
};

}  // namespace railjoint
