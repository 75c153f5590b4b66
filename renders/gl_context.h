#pragma once
// An OpenGL 3.3+ core-profile context of one back end (renders/gl_backend.h)
// that the off-screen renderer draws into through framebuffer objects of its
// own. Several contexts may live in one process and one thread (a test
// renders the same frame through both back ends): every use is bracketed by
// make_current() / release(), so no back end ever finds another's context
// current. No GL type appears here.

#include <memory>
#include <string>

#include "renders/gl_backend.h"

namespace railjoint {

class GlContext {
 public:
  virtual ~GlContext() = default;
  virtual GlBackend backend() const = 0;
  virtual void make_current() = 0;
  virtual void release() = 0;
  /// Address of a GL entry point for this context (core functions included), or nullptr.
  virtual void* proc_address(const char* name) const = 0;
};

/// Creates a context of that back end; throws std::runtime_error saying why
/// not (not built, no display, no core profile).
std::unique_ptr<GlContext> create_gl_context(GlBackend backend);

/// Makes `context` current for a scope.
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
