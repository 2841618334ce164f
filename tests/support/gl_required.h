// Tests that need an OpenGL context (their own, or the urdfsnap binary's) begin with
// URDFSNAP_REQUIRE_GL(), or URDFSNAP_REQUIRE_GL_BACKEND(backend) for one backend: where the GL
// factory cannot make one, the test is skipped with the factory's message, which says what each
// backend reported; under CI=true it fails instead, so that a broken CI machine is noticed rather
// than passing with every image test skipped. Link urdfsnap_gl.
#pragma once

#include <string>

#include <gtest/gtest.h>

#include "support/gl_probe.h"

// Skips (or, under CI=true, fails) the calling test or SetUp when `no_gl_reason` is not empty.
#define URDFSNAP_SKIP_WITHOUT_GL_IF(no_gl_reason)                                \
  do {                                                                          \
    if (const std::string& no_gl = (no_gl_reason); !no_gl.empty()) {           \
      if (::urdfsnap::test::InCi()) FAIL() << no_gl << " (CI=true: no skipping)"; \
      GTEST_SKIP() << no_gl;                                                    \
    }                                                                           \
  } while (false)

// ... when no context of the backend the urdfsnap binary would use can be made.
#define URDFSNAP_REQUIRE_GL() URDFSNAP_SKIP_WITHOUT_GL_IF(::urdfsnap::test::NoDefaultGlReason())

// ... when no context of `backend` (a gl::Backend) can be made.
#define URDFSNAP_REQUIRE_GL_BACKEND(backend) \
  URDFSNAP_SKIP_WITHOUT_GL_IF(::urdfsnap::test::NoGlReason(backend))
