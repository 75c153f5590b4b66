#pragma once
// An OpenGL 3.3 core-profile context of OSMesa (Mesa's llvmpipe: no window
// system, no GPU). The renderer draws into framebuffer objects of its own,
// so OSMesa's colour buffer is a token nothing is drawn into. libOSMesa is
// loaded by the first context (dlopen) and never unloaded, and the GL entry
// points come through OSMesaGetProcAddress (renders/DESIGN.md "One back
// end"). Private to renders/; include only in files that draw.

#include <GL/glcorearb.h>

#include <vector>

namespace railjoint {

#define RAILJOINT_GL_FUNCTIONS(X)                                                                        \
  X(PFNGLGETSTRINGPROC, GetString)                                                                       \
  X(PFNGLGETINTEGERVPROC, GetIntegerv)                                                                   \
  X(PFNGLGETERRORPROC, GetError)                                                                         \
  X(PFNGLCREATESHADERPROC, CreateShader)                                                                 \
  X(PFNGLSHADERSOURCEPROC, ShaderSource)                                                                 \
  X(PFNGLCOMPILESHADERPROC, CompileShader)                                                               \
  X(PFNGLGETSHADERIVPROC, GetShaderiv)                                                                   \
  X(PFNGLGETSHADERINFOLOGPROC, GetShaderInfoLog)                                                         \
  X(PFNGLDELETESHADERPROC, DeleteShader)                                                                 \
  X(PFNGLCREATEPROGRAMPROC, CreateProgram)                                                               \
  X(PFNGLATTACHSHADERPROC, AttachShader)                                                                 \
  X(PFNGLLINKPROGRAMPROC, LinkProgram)                                                                   \
  X(PFNGLGETPROGRAMIVPROC, GetProgramiv)                                                                 \
  X(PFNGLGETPROGRAMINFOLOGPROC, GetProgramInfoLog)                                                       \
  X(PFNGLDELETEPROGRAMPROC, DeleteProgram)                                                               \
  X(PFNGLUSEPROGRAMPROC, UseProgram)                                                                     \
  X(PFNGLGETUNIFORMLOCATIONPROC, GetUniformLocation)                                                     \
  X(PFNGLUNIFORM1IPROC, Uniform1i)                                                                       \
  X(PFNGLUNIFORM1FPROC, Uniform1f)                                                                       \
  X(PFNGLUNIFORM2FPROC, Uniform2f)                                                                       \
  X(PFNGLUNIFORM3FVPROC, Uniform3fv)                                                                     \
  X(PFNGLUNIFORMMATRIX3FVPROC, UniformMatrix3fv)                                                         \
  X(PFNGLUNIFORMMATRIX4FVPROC, UniformMatrix4fv)                                                         \
  X(PFNGLGENVERTEXARRAYSPROC, GenVertexArrays)                                                           \
  X(PFNGLBINDVERTEXARRAYPROC, BindVertexArray)                                                           \
  X(PFNGLGENBUFFERSPROC, GenBuffers)                                                                     \
  X(PFNGLBINDBUFFERPROC, BindBuffer)                                                                     \
  X(PFNGLBUFFERDATAPROC, BufferData)                                                                     \
  X(PFNGLENABLEVERTEXATTRIBARRAYPROC, EnableVertexAttribArray)                                           \
  X(PFNGLVERTEXATTRIBPOINTERPROC, VertexAttribPointer)                                                   \
  X(PFNGLDRAWARRAYSPROC, DrawArrays)                                                                     \
  X(PFNGLENABLEPROC, Enable)                                                                             \
  X(PFNGLDISABLEPROC, Disable)                                                                           \
  X(PFNGLDEPTHFUNCPROC, DepthFunc)                                                                       \
  X(PFNGLBLENDFUNCPROC, BlendFunc)                                                                       \
  X(PFNGLDEPTHMASKPROC, DepthMask)                                                                       \
  X(PFNGLVIEWPORTPROC, Viewport)                                                                         \
  X(PFNGLSCISSORPROC, Scissor)                                                                           \
  X(PFNGLCLEARCOLORPROC, ClearColor)                                                                     \
  X(PFNGLCLEARPROC, Clear)                                                                               \
  X(PFNGLREADPIXELSPROC, ReadPixels)                                                                     \
  X(PFNGLGENFRAMEBUFFERSPROC, GenFramebuffers)                                                           \
  X(PFNGLBINDFRAMEBUFFERPROC, BindFramebuffer)                                                           \
  X(PFNGLFRAMEBUFFERRENDERBUFFERPROC, FramebufferRenderbuffer)                                           \
  X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, CheckFramebufferStatus)                                             \
  X(PFNGLBLITFRAMEBUFFERPROC, BlitFramebuffer)                                                           \
  X(PFNGLGENRENDERBUFFERSPROC, GenRenderbuffers)                                                         \
  X(PFNGLBINDRENDERBUFFERPROC, BindRenderbuffer)                                                         \
  X(PFNGLRENDERBUFFERSTORAGEMULTISAMPLEPROC, RenderbufferStorageMultisample)

/// One pointer per entry point, named without the "gl" prefix: gl.Clear(...).
struct GlFunctions {
#define RAILJOINT_GL_MEMBER(type, name) type name = nullptr;
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
