#pragma once
// An OpenGL 3.3 core-profile context of OSMesa, Mesa's off-screen library
// (llvmpipe): no window system, no device node, no GPU. The renderer draws
// into framebuffer objects of its own, so OSMesa's colour buffer is a token
// that nothing is drawn into. libOSMesa is loaded when the first context is
// made (dlopen), not linked: it maps LLVM (libLLVM-15, 100 MB), which every
// run of every command would map at start-up, though most never draw
// (docs/rendering.md, "GL back end"). Loaded once, never unloaded (Mesa's
// libraries do not support it). No OSMesa or GL type appears here.

#include <vector>

namespace railjoint {

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
  /// Address of a GL entry point (core functions included), or nullptr.
  void* proc_address(const char* name) const;

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
