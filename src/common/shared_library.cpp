// dlopen and dlsym with errors that say what is missing and how to get it.
#include "common/shared_library.h"

#include <dlfcn.h>

#include "common/error.h"

namespace urdfsnap {

SharedLibrary::SharedLibrary(const std::string& name, const std::string& remedy)
    : name_(name), handle_(dlopen(name.c_str(), RTLD_NOW | RTLD_LOCAL)) {
  if (!handle_) throw Error("cannot load " + name_ + " (" + dlerror() + "); " + remedy);
}

void* SharedLibrary::Symbol(const char* name) const {
  void* symbol = dlsym(handle_, name);
  if (!symbol) throw Error(name_ + " has no " + name);
  return symbol;
}

}  // namespace urdfsnap
