// GL backend names without GL: parsing and printing, the compiled-in list, URDFSNAP_GL_BACKEND
// when no backend is asked for, and the factory's refusal of a backend this build lacks.
#include "gl/backend.h"

#include <algorithm>
#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

#include "common/error.h"
#include "gl/gl_context.h"

namespace urdfsnap::gl {
namespace {

// The message of the urdfsnap::Error fn throws ("" when it throws none).
template <typename Fn>
std::string ErrorOf(Fn fn) {
  try {
    fn();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(BackendTest, NamesParseBackToTheirBackend) {
  for (Backend backend : {Backend::kAuto, Backend::kOsMesa, Backend::kEgl}) {
    EXPECT_EQ(ParseBackend(BackendName(backend)), backend);
  }
  EXPECT_EQ(BackendName(Backend::kOsMesa), "osmesa");
}

TEST(BackendTest, UnknownNameListsTheValidOnesAndThoseCompiledIn) {
  const std::string message = ErrorOf([] { ParseBackend("vulkan"); });
  EXPECT_EQ(message, "unknown GL backend 'vulkan': expected auto, osmesa or egl (compiled in: " +
                         CompiledInBackendNames() + ")");
  EXPECT_NE(ErrorOf([] { ParseBackend("EGL"); }), "");  // names are lower case, as typed
}

TEST(BackendTest, CompiledInBackendsAreConcreteAndInAutosOrder) {
  const auto& backends = CompiledInBackends();
  ASSERT_FALSE(backends.empty());
  EXPECT_EQ(backends.size(), std::size_t{URDFSNAP_WITH_OSMESA + URDFSNAP_WITH_EGL});
  if (URDFSNAP_WITH_OSMESA) {
    EXPECT_EQ(backends.front(), Backend::kOsMesa);
  }
  if (URDFSNAP_WITH_EGL) {
    EXPECT_EQ(backends.back(), Backend::kEgl);
  }
}

TEST(BackendTest, RequestedBackendWinsOverTheEnvironment) {
  setenv(kBackendVariable, "egl", 1);
  EXPECT_EQ(ResolveBackend(Backend::kOsMesa), Backend::kOsMesa);
  EXPECT_EQ(ResolveBackend(std::nullopt), Backend::kEgl);
  unsetenv(kBackendVariable);
}

TEST(BackendTest, UnsetOrEmptyEnvironmentMeansAuto) {
  unsetenv(kBackendVariable);
  EXPECT_EQ(ResolveBackend(std::nullopt), Backend::kAuto);
  setenv(kBackendVariable, "", 1);
  EXPECT_EQ(ResolveBackend(std::nullopt), Backend::kAuto);
  unsetenv(kBackendVariable);
}

TEST(BackendTest, BadEnvironmentValueNamesTheVariable) {
  setenv(kBackendVariable, "gpu", 1);
  EXPECT_EQ(ErrorOf([] { ResolveBackend(std::nullopt); }),
            "URDFSNAP_GL_BACKEND=gpu: unknown GL backend 'gpu': expected auto, osmesa or egl "
            "(compiled in: " + CompiledInBackendNames() + ")");
  // the factory reports it before trying any backend
  EXPECT_EQ(ErrorOf([] { CreateGlContext(std::nullopt); }).rfind("URDFSNAP_GL_BACKEND=gpu: ", 0), 0u);
  unsetenv(kBackendVariable);
}

TEST(BackendTest, BackendNotCompiledInIsAClearError) {
  int missing = 0;
  EXPECT_EQ(ErrorOf([] { CheckCompiledIn(Backend::kAuto); }), "");
  for (Backend backend : {Backend::kOsMesa, Backend::kEgl}) {
    if (std::find(CompiledInBackends().begin(), CompiledInBackends().end(), backend) !=
        CompiledInBackends().end()) {
      EXPECT_EQ(ErrorOf([&] { CheckCompiledIn(backend); }), "");
      continue;
    }
    ++missing;
    const std::string option = backend == Backend::kOsMesa ? "URDFSNAP_WITH_OSMESA" : "URDFSNAP_WITH_EGL";
    const std::string message = "GL backend '" + std::string(BackendName(backend)) +
                                "' is not compiled into this urdfsnap (built with " + option +
                                "=OFF); compiled in: " + CompiledInBackendNames();
    EXPECT_EQ(ErrorOf([&] { CheckCompiledIn(backend); }), message);
    EXPECT_EQ(ErrorOf([&] { CreateGlContext(backend); }), "cannot make an OpenGL context: " + message);
  }
  if (missing == 0) GTEST_SKIP() << "every backend is compiled into this build";
}

}  // namespace
}  // namespace urdfsnap::gl
