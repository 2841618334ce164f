// OSMesa implementation of GlContext. libOSMesa is opened with dlopen on the first context, not
// linked, so that only commands which render pay for loading it (and LLVM behind it).
#include "gl/gl_context.h"

#include "gl/gl_api.h"  // before GL/osmesa.h, whose GL/gl.h would hide GL 1.1's typedefs

#include <GL/osmesa.h>
#include <dlfcn.h>

#include <array>
#include <future>
#include <mutex>
#include <string>

#include "common/error.h"

namespace urdfsnap::gl {

namespace {

// The OSMesa entry points used, looked up with dlsym (GL/osmesa.h declares them).
struct OsMesaLibrary {
  decltype(&OSMesaCreateContextAttribs) create_context = nullptr;
  decltype(&OSMesaMakeCurrent) make_current = nullptr;
  decltype(&OSMesaDestroyContext) destroy_context = nullptr;
};

template <typename Fn>
Fn Symbol(void* library, const char* name) {
  void* symbol = dlsym(library, name);
  if (!symbol) throw Error(std::string(URDFSNAP_OSMESA_LIBRARY " has no ") + name);
  return reinterpret_cast<Fn>(symbol);
}

// Opens libOSMesa once per process (never closed: Mesa does not support unloading) and fills
// the GL function table.
const OsMesaLibrary& LoadOsMesa() {
  static OsMesaLibrary library;
  static std::once_flag once;
  std::call_once(once, [] {
    void* handle = dlopen(URDFSNAP_OSMESA_LIBRARY, RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      throw Error(std::string("cannot load ") + URDFSNAP_OSMESA_LIBRARY + " (" + dlerror() +
                  "); install Debian's libosmesa6");
    }
    OsMesaLibrary loaded;
    loaded.create_context =
        Symbol<decltype(loaded.create_context)>(handle, "OSMesaCreateContextAttribs");
    loaded.make_current = Symbol<decltype(loaded.make_current)>(handle, "OSMesaMakeCurrent");
    loaded.destroy_context =
        Symbol<decltype(loaded.destroy_context)>(handle, "OSMesaDestroyContext");
    LoadGlFunctions(Symbol<decltype(&OSMesaGetProcAddress)>(handle, "OSMesaGetProcAddress"));
    library = loaded;
  });
  return library;
}

class OsMesaContext final : public GlContext {
 public:
  OsMesaContext() : library_(LoadOsMesa()) {
    const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 0,
                              OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION, 3,
                              OSMESA_CONTEXT_MINOR_VERSION, 3, 0};
    context_ = library_.create_context(attributes, nullptr);
    if (!context_) throw Error("OSMesa could not create an OpenGL 3.3 core context");
    MakeCurrent();
  }
  ~OsMesaContext() override { library_.destroy_context(context_); }

  void MakeCurrent() override {
    if (!library_.make_current(context_, placeholder_.data(), GL_UNSIGNED_BYTE, 1, 1)) {
      throw Error("OSMesa could not make its OpenGL context current");
    }
  }

 private:
  const OsMesaLibrary& library_;
  OSMesaContext context_ = nullptr;
  std::array<unsigned char, 4> placeholder_{};
};

}  // namespace

std::unique_ptr<GlContext> CreateOsMesaContext() { return std::make_unique<OsMesaContext>(); }

std::future<void> StartLoadingGl() {
  return std::async(std::launch::async, [] {
    try {
      LoadOsMesa();
    } catch (const Error&) {
      // CreateOsMesaContext tries again and reports it
    }
  });
}

}  // namespace urdfsnap::gl
