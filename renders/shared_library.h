#pragma once
// A GL back end's shared library, loaded when a command first draws (dlopen)
// rather than linked: OSMesa pulls in LLVM (libLLVM-15, 100 MB) and EGL
// Mesa's drivers, which the dynamic loader mapped into every run of every
// command at start-up, though most never draw. Loaded once per process and
// never unloaded (Mesa's libraries do not support being unloaded).

#include <string>

namespace railjoint {

class SharedLibrary {
 public:
  /// dlopen(soname). Throws std::runtime_error naming the library, the
  /// loader's reason and the Debian package that provides it.
  SharedLibrary(const char* soname, const char* debian_package);

  /// The address of `name` in it. Throws std::runtime_error when it lacks it.
  void* symbol(const char* name) const;

  /// symbol() as a function pointer of type F.
  template <class F>
  F function(const char* name) const {
    return reinterpret_cast<F>(symbol(name));
  }

 private:
  void* handle_ = nullptr;
  std::string soname_;
  std::string package_;
};

}  // namespace railjoint
