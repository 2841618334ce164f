// A library opened at run time with dlopen (the GL backends' libOSMesa and libEGL), never closed:
// Mesa does not support unloading. Internal to the GL library.
#pragma once

#include <string>

namespace urdfsnap::gl {

class SharedLibrary {
 public:
  // Opens `soname`. Throws urdfsnap::Error with the loader's reason and the Debian packages
  // (`packages`, e.g. "libosmesa6") that install it.
  SharedLibrary(const char* soname, const char* packages);

  // The function `name`, as a pointer of type Fn. Throws urdfsnap::Error when the library has none.
  template <typename Fn>
  Fn Get(const char* name) const {
    return reinterpret_cast<Fn>(Symbol(name));
  }

 private:
  void* Symbol(const char* name) const;
  std::string soname_;
  void* handle_;
};

}  // namespace urdfsnap::gl
