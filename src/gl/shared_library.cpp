// dlopen and dlsym with errors that say what is missing and how to install it.
#include "gl/shared_library.h"

#include <dlfcn.h>

#include "common/error.h"

namespace urdfsnap::gl {

SharedLibrary::SharedLibrary(const char* soname, const char* packages)
    : soname_(soname), handle_(dlopen(soname, RTLD_NOW | RTLD_LOCAL)) {
  if (!handle_) {
    throw Error("cannot load " + soname_ + " (" + dlerror() + "); install Debian's " + packages);
  }
}

void* SharedLibrary::Symbol(const char* name) const {
  void* symbol = dlsym(handle_, name);
  if (!symbol) throw Error(soname_ + " has no " + name);
  return symbol;
}

}  // namespace urdfsnap::gl
