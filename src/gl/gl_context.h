// The off-screen OpenGL context behind one small interface: OSMesa (llvmpipe) today, EGL later.
// Rendering goes to framebuffer objects, so the context's own buffer is a 1x1 placeholder.
#pragma once

#include <future>
#include <memory>

namespace urdfsnap::gl {

class GlContext {
 public:
  virtual ~GlContext() = default;
  // Makes this context current on the calling thread.
  virtual void MakeCurrent() = 0;
};

// An OpenGL 3.3 core-profile context from OSMesa. Throws urdfsnap::Error when Mesa cannot make one.
std::unique_ptr<GlContext> CreateOsMesaContext();

// Starts loading libOSMesa (and LLVM behind it, ~0.1 s) on a background thread, so that a command
// can read its model meanwhile; CreateOsMesaContext waits for it. A failure is reported by
// CreateOsMesaContext. Keep the returned future until the command ends, also when it fails:
// its destructor waits for the load, and a process must not exit while dlopen runs constructors.
[[nodiscard]] std::future<void> StartLoadingGl();

}  // namespace urdfsnap::gl
