// The OSMesa backend: Mesa's off-screen library, llvmpipe on the CPU. libOSMesa is opened with
// dlopen on the first context, not linked, so that only commands which render pay for loading it
// (and LLVM behind it). Mesa 25.1 removed OSMesa; the EGL backend is its successor.
#include "gl/internal/gl_api.h"  // before GL/osmesa.h, whose GL/gl.h would hide GL 1.1's typedefs

#include <GL/osmesa.h>

#include <array>
#include <string>

#include "common/error.h"
#include "gl/internal/gl_backends.h"
#include "common/shared_library.h"

namespace urdfsnap::gl {

namespace {

// The OSMesa entry points used, looked up with dlsym (GL/osmesa.h declares them).
struct OsMesaLibrary {
  decltype(&OSMesaCreateContextAttribs) create_context = nullptr;
  decltype(&OSMesaMakeCurrent) make_current = nullptr;
  decltype(&OSMesaDestroyContext) destroy_context = nullptr;
  decltype(&OSMesaGetProcAddress) get_proc_address = nullptr;
};

OsMesaLibrary OpenOsMesa() {
  const SharedLibrary library(URDFSNAP_OSMESA_LIBRARY, "install Debian's libosmesa6");
  OsMesaLibrary osmesa;
  osmesa.create_context =
      library.Get<decltype(osmesa.create_context)>("OSMesaCreateContextAttribs");
  osmesa.make_current = library.Get<decltype(osmesa.make_current)>("OSMesaMakeCurrent");
  osmesa.destroy_context = library.Get<decltype(osmesa.destroy_context)>("OSMesaDestroyContext");
  osmesa.get_proc_address =
      library.Get<decltype(osmesa.get_proc_address)>("OSMesaGetProcAddress");
  return osmesa;
}

// Opens libOSMesa once per process (never closed: Mesa does not support unloading).
const OsMesaLibrary& OsMesa() {
  return LoadOnce([] { return OpenOsMesa(); });
}

class OsMesaContext final : public GlContext {
 public:
  OsMesaContext() : library_(OsMesa()) {
    const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 0,
                              OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION, 3,
                              OSMESA_CONTEXT_MINOR_VERSION, 3, 0};
    context_ = library_.create_context(attributes, nullptr);
    if (!context_) throw Error("OSMesa could not create an OpenGL 3.3 core context");
    MakeCurrent();
    description_ = DescribeCurrentContext("OSMesa");
  }
  ~OsMesaContext() override { library_.destroy_context(context_); }

  void MakeCurrent() override {
    // the context's own buffer is a 1x1 placeholder: drawing goes to framebuffer objects
    if (!library_.make_current(context_, placeholder_.data(), GL_UNSIGNED_BYTE, 1, 1)) {
      throw Error("OSMesa could not make its OpenGL context current");
    }
    UseGlFunctionsFrom(library_.get_proc_address);
  }
  void Release() override { library_.make_current(nullptr, nullptr, 0, 0, 0); }
  Backend backend() const override { return Backend::kOsMesa; }
  const std::string& description() const override { return description_; }

 private:
  const OsMesaLibrary& library_;
  OSMesaContext context_ = nullptr;
  std::array<unsigned char, 4> placeholder_{};
  std::string description_;
};

}  // namespace

void LoadOsMesa() { OsMesa(); }

std::unique_ptr<GlContext> CreateOsMesaContext() { return std::make_unique<OsMesaContext>(); }

}  // namespace urdfsnap::gl
