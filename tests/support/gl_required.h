// Tests that need an OpenGL context (their own, or the urdfsnap binary's) begin with
// URDFSNAP_REQUIRE_GL(): where the GL factory cannot make one, the test is skipped with the
// factory's message, which says what each backend reported; under CI=true it fails instead, so
// that a broken CI machine is noticed rather than passing with every image test skipped.
// Link urdfsnap_gl.
#pragma once

#include <string>

#include <gtest/gtest.h>

#include "support/gl_probe.h"

// Skips (or, under CI=true, fails) the calling test or SetUp when no GL context can be made.
#define URDFSNAP_REQUIRE_GL()                                                         \
  do {                                                                                \
    if (const std::string& no_gl = ::urdfsnap::test::NoDefaultGlReason(); !no_gl.empty()) { \
      if (::urdfsnap::test::InCi()) FAIL() << no_gl << " (CI=true: no skipping)";     \
      GTEST_SKIP() << no_gl;                                                          \
    }                                                                                 \
  } while (false)
