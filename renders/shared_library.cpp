#include "renders/shared_library.h"

#include <stdexcept>

#include <dlfcn.h>

namespace railjoint {

SharedLibrary::SharedLibrary(const char* soname, const char* debian_package)
    : soname_(soname), package_(debian_package) {
  handle_ = dlopen(soname, RTLD_NOW | RTLD_LOCAL);
  if (handle_ == nullptr) {
    const char* reason = dlerror();
    throw std::runtime_error("renderer: cannot load " + soname_ + " (" + (reason != nullptr ? reason : "unknown") +
                             "); install Debian's " + package_);
  }
}

void* SharedLibrary::symbol(const char* name) const {
  dlerror();  // clear an older error: a symbol may be null legitimately
  void* address = dlsym(handle_, name);
  if (address == nullptr) {
    throw std::runtime_error("renderer: " + soname_ + " has no " + name + " (install Debian's " + package_ + ")");
  }
  return address;
}

}  // namespace railjoint
