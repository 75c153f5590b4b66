#pragma once
// The OpenGL entry points the renderer calls, loaded from the current
// context (OSMesaGetProcAddress) rather than linked: libOSMesa is loaded when
// a command first draws (renders/gl_context.h). libepoxy, the loader library,
// cannot load OSMesa's entry points. Private to renders/; include only in
// files that draw.

#include <GL/glcorearb.h>

namespace railjoint {

class GlContext;

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

/// Loads every entry point from `context` (which must be current); throws
/// std::runtime_error naming the first one missing.
GlFunctions load_gl_functions(const GlContext& context);

}  // namespace railjoint
