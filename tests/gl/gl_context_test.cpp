// The GL context factory with real contexts: each compiled-in backend makes an OpenGL 3.3+ core
// context that says what it is, auto takes the first backend that works, and renderers of both
// backends can take turns in one process (the GL function table follows the current context).
#include "gl/gl_context.h"

#include <gtest/gtest.h>

#include "front_view.h"
#include "gl/scene_renderer.h"
#include "scene/primitive_meshes.h"
#include "support/gl_required.h"

namespace urdfsnap::gl {
namespace {

class GlContextTest : public ::testing::TestWithParam<Backend> {};

}  // namespace

// the backend's name in test names and messages
void PrintTo(Backend backend, std::ostream* out) { *out << BackendName(backend); }

namespace {

TEST_P(GlContextTest, MakesACoreContextThatSaysWhatItIs) {
  URDFSNAP_REQUIRE_GL_BACKEND(GetParam());
  const std::unique_ptr<GlContext> context = CreateGlContext(GetParam());
  EXPECT_EQ(context->backend(), GetParam());
  const std::string& description = context->description();
  EXPECT_EQ(description.rfind(GetParam() == Backend::kEgl ? "EGL (" : "OSMesa, ", 0), 0u) << description;
  // "..., <GL_RENDERER>, OpenGL 4.5 core, Mesa 22.3.6": at least the 3.3 asked for, core profile
  const size_t gl = description.find(", OpenGL ");
  ASSERT_NE(gl, std::string::npos) << description;
  EXPECT_GE(std::stod(description.substr(gl + 9)), 3.3) << description;
  EXPECT_NE(description.find(" core"), std::string::npos) << description;
  context->MakeCurrent();
}

TEST_P(GlContextTest, SaysWhoAskedForItAndTellsTheRendererChoiceOnce) {
  URDFSNAP_REQUIRE_GL_BACKEND(GetParam());
  const std::string name(BackendName(GetParam()));
  EXPECT_EQ(CreateGlContext(GetParam())->reason(), "requested " + name);
  const std::unique_ptr<GlContext> context = CreateGlContext(GetParam(), "--gl-backend");
  EXPECT_EQ(context->reason(), "--gl-backend " + name);
  EXPECT_EQ(context->Summary(), name + " (--gl-backend " + name + "): " + context->description());
  std::vector<std::string> told;
  BackendChoice choice(GetParam());
  choice.asked_by = "--gl-backend";
  choice.on_context = [&](const std::string& summary) { told.push_back(summary); };
  const SceneRenderer renderer(0, choice);
  EXPECT_EQ(told, std::vector<std::string>{renderer.Summary()});
  EXPECT_EQ(renderer.Summary(), context->Summary());
}

INSTANTIATE_TEST_SUITE_P(CompiledIn, GlContextTest, ::testing::ValuesIn(CompiledInBackends()),
                         [](const auto& info) { return std::string(BackendName(info.param)); });

TEST(GlContextFactoryTest, AutoTakesTheFirstCompiledInBackendThatWorks) {
  URDFSNAP_REQUIRE_GL_BACKEND(Backend::kAuto);
  Backend expected = Backend::kAuto;
  for (Backend backend : CompiledInBackends()) {
    if (test::NoGlReason(backend).empty()) {
      expected = backend;
      break;
    }
  }
  EXPECT_EQ(CreateGlContext(Backend::kAuto)->backend(), expected);
}

// A unit box whose +X face, at x = 0, faces the camera (FrontView) and the head-light: n · l = 1,
// so the centre pixel of a 64x48 image is exactly the diffuse colour `rgb`.
scene::Scene BoxFacingTheCamera(const Eigen::Vector3f& rgb) {
  scene::Scene scene;
  scene.background = {48 / 255.f, 48 / 255.f, 48 / 255.f};
  scene::DrawItem box;
  box.mesh = scene::UnitBoxMesh();
  box.X_FG = Eigen::Translation3d(-0.5, 0, 0) * Eigen::Affine3d::Identity();
  box.rgba << rgb, 1;
  scene.items.push_back(box);
  return scene;
}

TEST(GlContextFactoryTest, BackendsTakeTurnsInOneProcess) {
  if (CompiledInBackends().size() < 2) GTEST_SKIP() << "one backend compiled in";
  URDFSNAP_REQUIRE_GL_BACKEND(Backend::kOsMesa);
  URDFSNAP_REQUIRE_GL_BACKEND(Backend::kEgl);
  // each backend draws its own colour: a call that reached the other backend's context would
  // show up as the other colour (or as the background)
  SceneRenderer osmesa(4, {Backend::kOsMesa});
  SceneRenderer egl(4, {Backend::kEgl});
  const scene::Scene red = BoxFacingTheCamera({1, 0, 0}), blue = BoxFacingTheCamera({0, 0, 1});
  for (int round = 0; round < 3; ++round) {
    for (SceneRenderer* renderer : {&osmesa, &egl, &egl, &osmesa}) {
      const bool is_egl = renderer == &egl;
      const image::Image image = renderer->Render(is_egl ? blue : red, FrontView(), 64, 48).colour;
      const size_t centre = (24 * 64 + 32) * 3;
      const std::array<int, 3> pixel{image.rgb[centre], image.rgb[centre + 1], image.rgb[centre + 2]};
      EXPECT_EQ(pixel, (is_egl ? std::array<int, 3>{0, 0, 255} : std::array<int, 3>{255, 0, 0}))
          << BackendName(renderer->backend()) << ", round " << round;
    }
  }
}

}  // namespace
}  // namespace urdfsnap::gl
