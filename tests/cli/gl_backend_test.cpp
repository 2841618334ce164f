// The GL backends from the command line: --version names those compiled in and the one used here,
// URDFSNAP_GL_BACKEND and URDFSNAP_EGL_DEVICE errors are one located line (status 2, nothing
// written), and commands that do not render never load a GL library (the reason both backends
// are opened with dlopen).
#include <string>

#include <gtest/gtest.h>

#include "cli_fixture.h"
#include "gl/backend.h"

namespace urdfsnap::cli_test {
namespace {

bool Contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

bool EglCompiledIn() { return Contains(gl::CompiledInBackendNames(), "egl"); }

using GlBackendTest = CliTest;

TEST_F(GlBackendTest, VersionNamesTheBackendsCompiledInAndTheOneUsedHere) {
  URDFSNAP_REQUIRE_GL();
  const Result r = RunUrdfsnap("--version");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output.rfind("urdfsnap 0.1.0\nGL backends compiled in: " + gl::CompiledInBackendNames() +
                               " (auto takes the first that makes a context)\nGL backend here: ", 0),
            0u)
      << r.output;
  EXPECT_TRUE(Contains(r.output, ", OpenGL ")) << r.output;
  for (const std::string backend : {"osmesa", "egl"}) {
    if (!Contains(gl::CompiledInBackendNames(), backend)) continue;
    const Result chosen = RunUrdfsnap("--version", "URDFSNAP_GL_BACKEND=" + backend);
    EXPECT_TRUE(Contains(chosen.output, "GL backend here: " + backend + " (URDFSNAP_GL_BACKEND=" +
                                            backend + "): " + (backend == "egl" ? "EGL (" : "OSMesa, ")))
        << chosen.output;
  }
}

TEST_F(GlBackendTest, BadBackendVariableIsOneErrorLineAndWritesNothing) {
  const Result r = RunUrdfsnap("render " + kMrm + " -o " + Path("a.png"), "URDFSNAP_GL_BACKEND=vulkan");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.output, "urdfsnap: error: URDFSNAP_GL_BACKEND=vulkan: unknown GL backend 'vulkan': "
                      "expected auto, osmesa or egl (compiled in: " + gl::CompiledInBackendNames() + ")\n");
  EXPECT_EQ(ReadBytes(Path("a.png")), "");
}

TEST_F(GlBackendTest, EglDeviceSoftwareIsMesasLlvmpipe) {
  if (!EglCompiledIn()) GTEST_SKIP() << "EGL is not compiled in";
  URDFSNAP_REQUIRE_GL_BACKEND(gl::Backend::kEgl);
  const Result r = RunUrdfsnap("--version", "URDFSNAP_GL_BACKEND=egl URDFSNAP_EGL_DEVICE=software");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(Contains(r.output, ": software), llvmpipe")) << r.output;
}

TEST_F(GlBackendTest, BadEglDeviceIsOneErrorLineNamingTheVariable) {
  if (!EglCompiledIn()) GTEST_SKIP() << "EGL is not compiled in";
  URDFSNAP_REQUIRE_GL_BACKEND(gl::Backend::kEgl);  // libEGL's own failures come first
  const std::string render = "render " + kMrm + " -o " + Path("a.png");
  Result r = RunUrdfsnap(render, "URDFSNAP_GL_BACKEND=egl URDFSNAP_EGL_DEVICE=gpu");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.output, "urdfsnap: error: cannot make an OpenGL context (GL backend egl): egl: "
                      "URDFSNAP_EGL_DEVICE=gpu: expected auto, software, a device number or a "
                      "/dev/dri path\n");
  // a device that is not there: the message lists the ones libEGL has
  r = RunUrdfsnap(render, "URDFSNAP_GL_BACKEND=egl URDFSNAP_EGL_DEVICE=/dev/dri/renderD199");
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(Contains(r.output, "URDFSNAP_EGL_DEVICE=/dev/dri/renderD199: no such EGL device (libEGL lists "))
      << r.output;
  EXPECT_EQ(ReadBytes(Path("a.png")), "");
}

TEST_F(GlBackendTest, CommandsThatDoNotRenderLoadNoGlLibrary) {
  // the dynamic loader's own account of every library it maps
  for (const std::string& command : {"info " + kMrm, "xacro " + kMrm}) {
    const Result r = RunUrdfsnap(command, "LD_DEBUG=files");
    ASSERT_EQ(r.status, 0) << command;
    ASSERT_TRUE(Contains(r.output, "file=libc.so")) << "LD_DEBUG had no effect: " << r.output;
    for (const char* library : {"libOSMesa", "libEGL", "libLLVM", "libGL"}) {
      EXPECT_FALSE(Contains(r.output, std::string("file=") + library)) << command << " loads " << library;
    }
  }
}

}  // namespace
}  // namespace urdfsnap::cli_test
