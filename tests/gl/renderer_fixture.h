// The GL tests' fixture: one SceneRenderer (4x multisampling) for a test suite, made by the first test
// that finds a GL context. Without one the tests are skipped with the GL factory's reason (failed
// under CI=true). ctest runs the GL tests once per backend with URDFSNAP_GL_BACKEND set, which
// the renderer follows.
#pragma once

#include <gtest/gtest.h>

#include "gl/scene_renderer.h"
#include "support/gl_required.h"

namespace urdfsnap::gl {

class RendererFixture : public ::testing::Test {
 protected:
  void SetUp() override {
    URDFSNAP_REQUIRE_GL();
    if (!renderer_) renderer_ = new SceneRenderer(4);
  }
  static void TearDownTestSuite() {
    delete renderer_;
    renderer_ = nullptr;
  }
  static inline SceneRenderer* renderer_ = nullptr;
};

}  // namespace urdfsnap::gl
