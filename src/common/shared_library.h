// A library opened at run time with dlopen, never closed (Mesa does not support unloading, and
// urdfsnap's modules are kept for the process): the GL backends' libOSMesa and libEGL, and
// urdfsnap's own modules (common/module_loader.h).
#pragma once

#include <string>

namespace urdfsnap {

class SharedLibrary {
 public:
  // Opens `name` (a soname searched as the loader searches, or a path). Throws urdfsnap::Error
  // "cannot load NAME (the loader's reason); REMEDY", where `remedy` says how to get it (e.g.
  // "install Debian's libosmesa6").
  SharedLibrary(const std::string& name, const std::string& remedy);

  // The symbol `name`, as a pointer of type T (a function, or data). Throws urdfsnap::Error when the
  // library has none.
  template <typename T>
  T Get(const char* name) const {
    return reinterpret_cast<T>(Symbol(name));
  }

  const std::string& name() const { return name_; }

 private:
  void* Symbol(const char* name) const;
  std::string name_;
  void* handle_;
};

}  // namespace urdfsnap
