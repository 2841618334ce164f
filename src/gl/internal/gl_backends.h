// What each compiled-in backend gives the factory (gl_context.cpp): loading its library once per
// process and making a context. Internal to the GL library; osmesa_context.cpp and
// egl_context.cpp implement it, each built only with its CMake option.
#pragma once

#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include "common/error.h"
#include "gl/gl_context.h"

namespace urdfsnap::gl {

#if URDFSNAP_WITH_OSMESA
// Opens libOSMesa (once per process, never closed). Throws urdfsnap::Error when it cannot.
void LoadOsMesa();
// Loads libOSMesa if needed and makes a context current. Throws urdfsnap::Error.
std::unique_ptr<GlContext> CreateOsMesaContext();
#endif

#if URDFSNAP_WITH_EGL
// Opens libEGL and initialises the display URDFSNAP_EGL_DEVICE selects (once per process).
// Throws urdfsnap::Error when it cannot.
void LoadEgl();
// Loads EGL if needed and makes a context current. Throws urdfsnap::Error.
std::unique_ptr<GlContext> CreateEglContext();
#endif

// The value of open() made once per process (per call site: each lambda is its own type), and
// kept; its failure is kept too and thrown again, so a library's warnings are printed once and
// the background load's failure costs CreateGlContext nothing. A mutex rather than
// std::call_once, whose waiters can hang when the first call throws.
template <typename Open>
const auto& LoadOnce(Open open) {
  static std::mutex mutex;
  static std::optional<decltype(open())> value;
  static std::optional<Error> failure;
  std::lock_guard<std::mutex> lock(mutex);
  if (failure) throw *failure;
  if (!value) {
    try {
      value = open();
    } catch (const Error& e) {
      failure = e;
      throw;
    }
  }
  return *value;
}

// "<backend_label>, <GL_RENDERER>, OpenGL <version>[ core][, <rest of GL_VERSION>]" for the
// context current on this thread.
std::string DescribeCurrentContext(const std::string& backend_label);

}  // namespace urdfsnap::gl
