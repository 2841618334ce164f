// Whether this machine can make an OpenGL context, for tests that need one (gl_required.h for
// GoogleTest, gl_guard.cpp for command-line tests). Link urdfsnap_gl.
#pragma once

#include <cstdlib>
#include <optional>
#include <memory>
#include <string>
#include <vector>

#include "common/error.h"
#include "gl/gl_context.h"

namespace urdfsnap::test {

// Why no context of `backend` (nullopt: URDFSNAP_GL_BACKEND, else auto, as the urdfsnap binary
// chooses) can be made here: the factory's message, or "" when one can.
inline std::string NoGlReason(std::optional<gl::Backend> backend) {
  try {
    // the context is kept until the process ends: one made and dropped just before the test
    // made its own crashed LeakSanitizer's exit-time tracer (signal 11) in the sanitizer build
    static auto* kept = new std::vector<std::unique_ptr<gl::GlContext>>;
    kept->push_back(gl::CreateGlContext(backend));
    return "";
  } catch (const Error& e) {
    return e.what();
  }
}

// NoGlReason(nullopt), found out once per process.
inline const std::string& NoDefaultGlReason() {
  static const std::string reason = NoGlReason(std::nullopt);
  return reason;
}

// CI sets CI=true: there a missing context fails the tests that need one instead of skipping them.
inline bool InCi() {
  const char* ci = std::getenv("CI");
  return ci && std::string(ci) == "true";
}

}  // namespace urdfsnap::test
