// The off-screen OpenGL context behind one small interface and one factory: OSMesa or EGL
// (backend.h), each opened with dlopen when the first context is made, so that commands which do
// not render never load Mesa and LLVM. Rendering goes to framebuffer objects: no context has a
// window or a drawable of its own that is drawn into.
#pragma once

#include <future>
#include <memory>
#include <optional>
#include <string>

#include "gl/backend.h"

namespace urdfsnap::gl {

class GlContext;

// An OpenGL 3.3 core-profile context from the backend ResolveBackend(requested) names: nullopt
// means "not given" (URDFSNAP_GL_BACKEND, else auto). Auto tries the compiled-in backends in
// order (OSMesa, then EGL) and takes the first that makes a context. `asked_by` names who gave
// `requested` in the context's reason (BackendChoice::asked_by). Throws urdfsnap::Error when
// URDFSNAP_GL_BACKEND is not a backend's name, when the backend asked for is not compiled in, or
// when no context can be made; the message then starts "cannot make an OpenGL context" and says
// what each backend tried reported.
std::unique_ptr<GlContext> CreateGlContext(std::optional<Backend> requested, const std::string& asked_by = "");

class GlContext {
 public:
  virtual ~GlContext() = default;
  // Makes this context current on the calling thread (and the GL function table its backend's).
  virtual void MakeCurrent() = 0;
  // Leaves the calling thread with no current context, so that another thread may make this one
  // current next (EGL refuses a context current on another thread: EGL_BAD_ACCESS).
  virtual void Release() = 0;
  // kOsMesa or kEgl, never kAuto.
  virtual Backend backend() const = 0;
  // One line naming the backend, GL_RENDERER and GL_VERSION, e.g. "EGL (surfaceless), llvmpipe
  // (LLVM 15.0.6, 256 bits), OpenGL 4.5 core, Mesa 22.3.6".
  virtual const std::string& description() const = 0;
  // Why the factory took this backend: who asked for it ("--gl-backend egl", "requested osmesa",
  // "URDFSNAP_GL_BACKEND=egl", "auto") and, for auto, what the backends before it reported, e.g.
  // "auto: osmesa failed: cannot load libOSMesa.so.8: ...".
  const std::string& reason() const { return reason_; }
  // "<backend> (<reason>): <description>", the line --verbose and --version print.
  std::string Summary() const;

 private:
  friend std::unique_ptr<GlContext> CreateGlContext(std::optional<Backend>, const std::string&);
  std::string reason_;
};

// Starts loading the library of the backend CreateGlContext(requested) would use first (OSMesa
// or libEGL with its display, and Mesa's LLVM behind either, ~0.1 s) on a background thread, so
// that a command can read its model meanwhile; CreateGlContext waits for it. Failures are left
// for CreateGlContext to report. Keep the returned future until the command ends, also when it
// fails: its destructor waits for the load, and a process must not exit while dlopen runs
// constructors.
[[nodiscard]] std::future<void> StartLoadingGl(std::optional<Backend> requested = std::nullopt);

// For `urdfsnap --version`: the compiled-in backends and what CreateGlContext(nullopt) makes on
// this machine, e.g. "GL backends compiled in: osmesa, egl\nGL backend auto on this machine:
// osmesa: OSMesa, llvmpipe (...)". Makes (and drops) a context to find out: about 0.1 s, the
// cost of loading Mesa. Never throws: a failure is part of the text.
std::string DescribeGlBackends();

}  // namespace urdfsnap::gl
