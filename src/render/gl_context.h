// The off-screen OpenGL context behind one small interface: OSMesa (llvmpipe) today, EGL later.
// Rendering goes to framebuffer objects, so the context's own buffer is a 1x1 placeholder.
#pragma once

#include <memory>

namespace urdfsnap::render {

class GlContext {
 public:
  virtual ~GlContext() = default;
  // Makes this context current on the calling thread.
  virtual void MakeCurrent() = 0;
};

// An OpenGL 3.3 core-profile context from OSMesa. Throws urdfsnap::Error when Mesa cannot make one.
std::unique_ptr<GlContext> CreateOsMesaContext();

// Starts loading libOSMesa (and LLVM behind it, ~0.1 s) on a background thread, so that a command
// can read its model meanwhile; CreateOsMesaContext waits for it. Optional, and safe to call
// more than once; a failure is reported by CreateOsMesaContext.
void StartLoadingGl();

// Waits for a load StartLoadingGl began (returns at once if none did). Call it before main returns:
// exit() runs the atexit handlers that LLVM's static objects register while loading, LIFO, so a
// load still running then would find LLVM torn down under it (seen as a hang in LLVM's pass
// registry on fast error exits).
void FinishLoadingGl();

}  // namespace urdfsnap::render
