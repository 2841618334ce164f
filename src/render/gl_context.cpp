// OSMesa implementation of GlContext.
#include "render/gl_context.h"

#include <GL/osmesa.h>

#include <array>

#include "common/error.h"

namespace urdfsnap::render {

namespace {

class OsMesaContext final : public GlContext {
 public:
  OsMesaContext() {
    const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 0,
                              OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION, 3,
                              OSMESA_CONTEXT_MINOR_VERSION, 3, 0};
    context_ = OSMesaCreateContextAttribs(attributes, nullptr);
    if (!context_) throw Error("OSMesa could not create an OpenGL 3.3 core context");
    MakeCurrent();
  }
  ~OsMesaContext() override { OSMesaDestroyContext(context_); }

  void MakeCurrent() override {
    if (!OSMesaMakeCurrent(context_, placeholder_.data(), GL_UNSIGNED_BYTE, 1, 1)) {
      throw Error("OSMesa could not make its OpenGL context current");
    }
  }

 private:
  OSMesaContext context_ = nullptr;
  std::array<unsigned char, 4> placeholder_{};
};

}  // namespace

std::unique_ptr<GlContext> CreateOsMesaContext() { return std::make_unique<OsMesaContext>(); }

}  // namespace urdfsnap::render
