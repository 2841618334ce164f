// The GL backends from the command line: --version --verbose names those compiled in and the one
// used here (--version alone makes no context), URDFSNAP_GL_BACKEND and URDFSNAP_EGL_DEVICE errors
// are one located line (status 2, nothing written), commands that do not render never load a GL
// library (the reason both backends are opened with dlopen), and --gl-backend and --verbose on
// every command that renders: the option draws what the variable does, beats it, and says which
// backend was taken and why.
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "cli_fixture.h"
#include "gl/backend.h"
#include "support/gl_probe.h"

namespace urdfsnap::cli_test {
namespace {

bool Contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

bool EglCompiledIn() { return Contains(gl::CompiledInBackendNames(), "egl"); }

using GlBackendTest = CliTest;

TEST_F(GlBackendTest, VersionAloneIsTheVersionString) {
  const Result r = RunUrdfsnap("--version");
  EXPECT_EQ(r.status, 0);
  EXPECT_EQ(r.output, "urdfsnap 0.1.0\n");
}

TEST_F(GlBackendTest, VerboseVersionNamesTheBackendsCompiledInAndTheOneUsedHere) {
  URDFSNAP_REQUIRE_GL();
  const Result r = RunUrdfsnap("--version --verbose");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output.rfind("urdfsnap 0.1.0\nGL backends compiled in: " + gl::CompiledInBackendNames() +
                               " (auto takes the first that makes a context)\nGL backend here: ", 0),
            0u)
      << r.output;
  EXPECT_TRUE(Contains(r.output, ", OpenGL ")) << r.output;
  for (const std::string backend : {"osmesa", "egl"}) {
    if (!Contains(gl::CompiledInBackendNames(), backend)) continue;
    const Result chosen = RunUrdfsnap("--verbose --version", "URDFSNAP_GL_BACKEND=" + backend);
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
  const Result r = RunUrdfsnap("--version --verbose", "URDFSNAP_GL_BACKEND=egl URDFSNAP_EGL_DEVICE=software");
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

// Every file under `folder` (relative path -> bytes).
std::map<std::string, std::string> FilesUnder(const std::string& folder) {
  std::map<std::string, std::string> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(folder)) {
    if (entry.is_regular_file()) {
      files[std::filesystem::relative(entry.path(), folder).string()] = ReadBytes(entry.path().string());
    }
  }
  return files;
}

// The commands that render, in an order that runs (the update before the check), each with what it
// needs to run on mrm and write into `folder`, where the snapshot suite `suite` is.
std::vector<std::pair<std::string, std::string>> RenderingCommands(const std::string& suite,
                                                                   const std::string& folder) {
  return {
      {"render", "render " + kMrm + " --size 160x120 -o " + folder + "/render.png"},
      {"snapshot update", "snapshot update " + suite},
      {"snapshot check", "snapshot check " + suite},
      {"animate", "animate " + kMrm + " --turntable --duration 0.2 --fps 10 --size 160x120 -o " + folder +
                      "/frames/%03d.png"},
      {"docs", "docs " + kMrm + " --animations none --size 160x120 -o " + folder + "/page"},
  };
}

TEST_F(GlBackendTest, UnknownBackendOptionIsOneErrorLineOnEveryCommandAndWritesNothing) {
  const std::string suite = Write("suite.yaml", "cases:\n  - name: home\n    model: " + kMrm + "\n");
  auto commands = RenderingCommands(suite, dir_.string());
  commands.emplace_back("serve", "serve " + kMrm + " --port 0");
  for (const auto& [name, command] : commands) {
    const Result r = RunUrdfsnap(command + " --gl-backend vulkan --verbose");
    EXPECT_EQ(r.status, 2) << name;
    EXPECT_EQ(r.output, "urdfsnap: error: --gl-backend: unknown GL backend 'vulkan': expected auto, osmesa "
                        "or egl (compiled in: " + gl::CompiledInBackendNames() + ") (see 'urdfsnap --help')\n")
        << name;
  }
  EXPECT_EQ(FilesUnder(dir_.string()).size(), 1u);  // the suite only
}

TEST_F(GlBackendTest, EveryRenderingCommandListsTheOptionsWithTheirDefaults) {
  for (const std::string command : {"render", "snapshot check", "snapshot update", "animate", "docs", "serve"}) {
    const Result r = RunUrdfsnap(command + " --help");
    ASSERT_EQ(r.status, 0) << command;
    for (const std::string option : {"--gl-backend NAME", "--verbose"}) {
      const size_t at = r.output.find("  " + option + " ");
      ASSERT_NE(at, std::string::npos) << command << " --help has no " << option << ":\n" << r.output;
      const std::string line = r.output.substr(at, r.output.find('\n', at) - at);
      EXPECT_NE(line.find("(default: "), std::string::npos) << command << ": " << line;
    }
  }
}

TEST_F(GlBackendTest, BackendNotCompiledInNamesTheOnesThatAre) {
  const std::string suite = Write("suite.yaml", "cases:\n  - name: home\n    model: " + kMrm + "\n");
  int missing = 0;
  for (const std::string backend : {"osmesa", "egl"}) {
    if (Contains(gl::CompiledInBackendNames(), backend)) continue;
    ++missing;
    const std::string message = "GL backend '" + backend + "' is not compiled into this urdfsnap (built with "
                                "URDFSNAP_WITH_" + (backend == "egl" ? "EGL" : "OSMESA") +
                                "=OFF); compiled in: " + gl::CompiledInBackendNames();
    // the option: refused with the command line, on every command
    auto commands = RenderingCommands(suite, dir_.string());
    commands.emplace_back("serve", "serve " + kMrm + " --port 0");
    for (const auto& [name, command] : commands) {
      const Result r = RunUrdfsnap(command + " --gl-backend " + backend);
      EXPECT_EQ(r.status, 2) << name;
      EXPECT_EQ(r.output, "urdfsnap: error: --gl-backend: " + message + " (see 'urdfsnap --help')\n") << name;
    }
    // the variable: when the context is to be made
    const Result r = RunUrdfsnap("render " + kMrm + " -o " + Path("a.png"), "URDFSNAP_GL_BACKEND=" + backend);
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.output, "urdfsnap: error: cannot make an OpenGL context: " + message + "\n");
  }
  if (missing == 0) GTEST_SKIP() << "every backend is compiled in";
  EXPECT_EQ(FilesUnder(dir_.string()).size(), 1u);  // the suite only
}

// Each compiled-in backend (one test per backend; not the backends this build lacks).
class GlBackendOptionTest : public CliTest, public ::testing::WithParamInterface<gl::Backend> {
 protected:
  void SetUp() override {
    CliTest::SetUp();
    URDFSNAP_REQUIRE_GL_BACKEND(GetParam());
  }
  std::string name() const { return std::string(gl::BackendName(GetParam())); }
  // "urdfsnap: GL backend NAME (REASON): " and what comes first in the context's description
  std::string VerboseLine(const std::string& reason) const {
    return "urdfsnap: GL backend " + name() + " (" + reason + "): " +
           (GetParam() == gl::Backend::kEgl ? "EGL (" : "OSMesa, ");
  }
};

size_t Count(const std::string& text, const std::string& part) {
  size_t count = 0;
  for (size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++count;
  return count;
}

TEST_P(GlBackendOptionTest, DrawsWhatTheVariableDrawsOnEveryCommandAndSaysSoOnce) {
  for (const std::string how : {"variable", "option"}) {
    std::filesystem::create_directories(Path(how));
    const std::string suite = Write(how + "/suite.yaml", "cases:\n  - name: home\n    model: " + kMrm +
                                                             "\n    size: 160x120\n    yaw: 1.2\n");
    for (const auto& [command_name, command] : RenderingCommands(suite, Path(how))) {
      SCOPED_TRACE(how + ": " + command_name);
      const Result r = how == "variable" ? RunUrdfsnap(command, "URDFSNAP_GL_BACKEND=" + name())
                                         : RunUrdfsnap(command + " --gl-backend " + name() + " --verbose");
      ASSERT_EQ(r.status, 0) << r.output;
      // --verbose: one line, when the context is made
      EXPECT_EQ(Count(r.output, "urdfsnap: GL backend "), how == "option" ? 1u : 0u) << r.output;
      if (how == "option") {
        EXPECT_TRUE(Contains(r.output, VerboseLine("--gl-backend " + name()))) << r.output;
      }
    }
  }
  // the same files, byte for byte: the render, the golden, the frames, the page
  const auto by_variable = FilesUnder(Path("variable"));
  EXPECT_EQ(by_variable.size(), FilesUnder(Path("option")).size());
  for (const char* file : {"home.png", "render.png", "frames/002.png", "page/index.html"}) {
    EXPECT_TRUE(by_variable.count(file)) << file;
  }
  EXPECT_TRUE(by_variable == FilesUnder(Path("option")));
}

TEST_P(GlBackendOptionTest, OptionBeatsTheVariable) {
  for (const std::string other : {"auto", "osmesa", "egl", "not-a-backend"}) {
    const Result r = RunUrdfsnap("render " + kMrm + " --size 160x120 -o " + Path("a.png") + " --gl-backend " +
                                     name() + " --verbose",
                                 "URDFSNAP_GL_BACKEND=" + other);
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_EQ(r.output.rfind(VerboseLine("--gl-backend " + name()), 0), 0u) << r.output;
  }
  // and the variable alone is named as the reason; no --verbose, no line
  Result r = RunUrdfsnap("render " + kMrm + " --size 160x120 -o " + Path("b.png") + " --verbose",
                         "URDFSNAP_GL_BACKEND=" + name());
  EXPECT_EQ(r.output.rfind(VerboseLine("URDFSNAP_GL_BACKEND=" + name()), 0), 0u) << r.output;
  r = RunUrdfsnap("render " + kMrm + " --size 160x120 -o " + Path("c.png") + " --gl-backend " + name());
  EXPECT_EQ(r.output, "");
  EXPECT_TRUE(ReadBytes(Path("a.png")) == ReadBytes(Path("b.png")));
  EXPECT_TRUE(ReadBytes(Path("a.png")) == ReadBytes(Path("c.png")));
}

INSTANTIATE_TEST_SUITE_P(CompiledIn, GlBackendOptionTest, ::testing::ValuesIn(gl::CompiledInBackends()),
                         [](const auto& info) { return std::string(gl::BackendName(info.param)); });

TEST_F(GlBackendTest, VerboseSaysWhyAutoTookEgl) {
  if (gl::CompiledInBackends().size() < 2) GTEST_SKIP() << "auto has only " << gl::CompiledInBackendNames();
  URDFSNAP_REQUIRE_GL_BACKEND(gl::Backend::kEgl);
  // a libOSMesa that cannot load, found first
  std::filesystem::create_directories(Path("no-osmesa"));
  Write("no-osmesa/libOSMesa.so.8", "");
  const std::string render = "render " + kMrm + " --size 160x120 --verbose -o ";
  for (const std::string option : {"", " --gl-backend auto"}) {
    const Result r = RunUrdfsnap(render + Path("auto.png") + option, "LD_LIBRARY_PATH=" + Path("no-osmesa"));
    ASSERT_EQ(r.status, 0) << r.output;
    const std::string asked = option.empty() ? "auto" : "--gl-backend auto";
    EXPECT_EQ(r.output.rfind("urdfsnap: GL backend egl (" + asked + ": osmesa failed: cannot load libOSMesa.so.8 (" +
                                 Path("no-osmesa/libOSMesa.so.8") + ": file too short); install Debian's libosmesa6): EGL (",
                             0),
              0u)
        << r.output;
  }
  ASSERT_EQ(RunUrdfsnap(render + Path("egl.png") + " --gl-backend egl").status, 0);
  EXPECT_TRUE(ReadBytes(Path("auto.png")) == ReadBytes(Path("egl.png")));
}

}  // namespace
}  // namespace urdfsnap::cli_test
