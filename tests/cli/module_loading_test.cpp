// What each command loads, read from the dynamic loader's own account (LD_DEBUG=files names every
// library mapped, linked or opened with dlopen): info, xacro, render, diff, snapshot and --version
// load neither FFmpeg, libwebp nor the HTTP server, nor assimp for a robot without meshes; a mesh
// robot loads the mesh module; animate loads the video module for a video and not for PNG frames;
// serve loads its server module. And a copy of the binary without its modules, or with broken
// ones, fails the commands that need them with one error line and runs the others.
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli_fixture.h"
#include "common/module_loader.h"

namespace urdfsnap::cli_test {
namespace {

namespace fs = std::filesystem;

const std::string kMrmXacro = (kSource / "models/mrm_description/urdf/mrm.xacro").string();
const std::string kGolden = (kSource / "tests/golden/mrm_zero.png").string();
const std::string kMeshbot = (kSource / "models/meshbot_description/urdf/meshbot.urdf").string();

// libraries only the video and serve modules may bring in, by the start of their file names
// (libbrotlidec is not among them: FreeType reads WOFF2 fonts with it)
const std::vector<std::string> kModuleLibraries = {
    "urdfsnap-meshes.so", "libassimp", "urdfsnap-video.so", "urdfsnap-serve.so", "libavcodec",
    "libavformat", "libavfilter", "libswscale", "libavutil", "libwebp", "libcpp-httplib", "libssl",
    "libcrypto", "libbrotlienc"};

// The single line a failed command prints, or a note of what it printed instead.
std::string OnlyLine(const Result& r) {
  if (r.output.empty() || r.output.find('\n') != r.output.size() - 1) {
    return "not one line: " + r.output;
  }
  return r.output;
}

// Runs `arguments` with the loader's account of every library it maps on (LD_DEBUG=files),
// expecting exit status `status`, and checks that it loaded every library of `loaded` and none of
// `not_loaded` (names or the start of names: "libavcodec", "urdfsnap-video.so").
Result ExpectLoads(const std::string& arguments, int status, const std::vector<std::string>& loaded,
                   const std::vector<std::string>& not_loaded) {
  const Result run = RunUrdfsnap(arguments, "LD_DEBUG=files");
  EXPECT_NE(run.output.find("file=libc.so"), std::string::npos) << "LD_DEBUG had no effect: " << run.output;
  EXPECT_EQ(run.status, status) << arguments << "\n" << run.output;
  // "file=/path/urdfsnap-video.so [0];  dynamically loaded by ..." or "file=libavcodec.so.59 [0]; ..."
  auto has = [&run](const std::string& library) {
    return run.output.find("file=" + library) != std::string::npos ||
           run.output.find("/" + library) != std::string::npos;
  };
  for (const std::string& library : loaded) {
    EXPECT_TRUE(has(library)) << "urdfsnap " << arguments << " does not load " << library;
  }
  for (const std::string& library : not_loaded) {
    EXPECT_FALSE(has(library)) << "urdfsnap " << arguments << " loads " << library;
  }
  return run;
}

using ModuleLoadingTest = CliTest;

TEST_F(ModuleLoadingTest, CommandsThatWriteNoAnimationLoadNoModule) {
  URDFSNAP_REQUIRE_GL();
  const std::string suite = Write("suite.yaml", "cases:\n  - name: home\n    model: " + kMrm +
                                                    "\n    golden: goldens/home.png\n");
  const std::vector<std::string> commands = {
      "--version",
      "info " + kMrm,
      "xacro " + kMrmXacro,
      "render " + kMrm + " -o " + Path("a.png"),
      "diff " + kGolden + " " + kGolden,
      "snapshot update " + suite,
      "snapshot check " + suite,
  };
  for (const std::string& command : commands) ExpectLoads(command, 0, {}, kModuleLibraries);
  // nor does --version make a GL context (only --version --verbose)
  ExpectLoads("--version", 0, {}, {"libOSMesa", "libEGL", "libLLVM", "libGL"});
}

TEST_F(ModuleLoadingTest, MeshRobotsLoadTheMeshModule) {
  URDFSNAP_REQUIRE_GL();
  ExpectLoads("render " + kMeshbot + " -o " + Path("a.png"), 0,
              {"urdfsnap-meshes.so", "libassimp"}, {"urdfsnap-video.so"});
}

TEST_F(ModuleLoadingTest, AnimateLoadsTheVideoModuleForVideosOnly) {
  URDFSNAP_REQUIRE_GL();
  const std::string animate = "animate " + kMrm + " --turntable --duration 0.1 --size 64x48 -o ";
  ExpectLoads(animate + Path("frames/%03d.png"), 0, {}, {"urdfsnap-video.so", "libavcodec"});
  ExpectLoads(animate + Path("a.mp4"), 0, {"urdfsnap-video.so", "libavcodec"}, {"urdfsnap-serve.so"});
}

TEST_F(ModuleLoadingTest, ServeLoadsItsServerModule) {
  URDFSNAP_REQUIRE_GL();
  // 192.0.2.1 (TEST-NET-1) is no address of this machine: the server is made, then cannot listen
  const Result serve = ExpectLoads("serve " + kMrm + " --bind 192.0.2.1 --port 0", 2,
                                   {"urdfsnap-serve.so", "libcpp-httplib"}, {"urdfsnap-video.so"});
  EXPECT_NE(serve.output.find("urdfsnap: error: cannot listen on 192.0.2.1:0"), std::string::npos)
      << serve.output;
}

// A copy of the binary in a folder of its own, with `modules` (file name -> bytes) beside it.
class BinaryCopyTest : public CliTest {
 protected:
  void SetUp() override {
    CliTest::SetUp();
    // a module installed on this machine would be found by the copy too
    for (const fs::path& folder : ModuleFolders()) {
      if (folder == fs::path(URDFSNAP_BINARY).parent_path()) continue;
      for (const char* name : {"urdfsnap-meshes.so", "urdfsnap-video.so", "urdfsnap-serve.so"}) {
        if (fs::exists(folder / name)) GTEST_SKIP() << (folder / name) << " is installed here";
      }
    }
    fs::create_directories(Path("bin"));
    fs::copy_file(URDFSNAP_BINARY, Path("bin/urdfsnap"));
  }
  Result Run(const std::string& arguments) { return RunProgram(Path("bin/urdfsnap"), arguments); }

  // the commands that need no module still work; the ones that do fail with `*_reason`
  void ExpectOnlyModuleCommandsFail(const std::string& mesh_reason, const std::string& video_reason,
                                    const std::string& serve_reason) {
    const Result meshes = Run("render " + kMeshbot + " -o " + Path("meshbot.png"));
    EXPECT_EQ(meshes.status, 2);
    EXPECT_EQ(OnlyLine(meshes).rfind("urdfsnap: error: ", 0), 0u) << meshes.output;
    EXPECT_NE(meshes.output.find(": the mesh file reader (assimp): " + mesh_reason), std::string::npos)
        << meshes.output;
    EXPECT_FALSE(fs::exists(Path("meshbot.png")));

    const std::string animate = "animate " + kMrm + " --turntable --duration 0.1 --size 64x48 -o ";
    const Result video = Run(animate + Path("a.gif"));
    EXPECT_EQ(video.status, 2);
    EXPECT_EQ(OnlyLine(video).rfind("urdfsnap: error: " + Path("a.gif") +
                                        ": the MP4, WebM, GIF and WebP codecs (FFmpeg, libwebp): ", 0),
              0u)
        << video.output;
    EXPECT_NE(video.output.find(video_reason), std::string::npos) << video.output;
    EXPECT_FALSE(fs::exists(Path("a.gif")));

    const Result serve = Run("serve " + kMrm + " --port 0");
    EXPECT_EQ(serve.status, 2);
    EXPECT_EQ(OnlyLine(serve).rfind("urdfsnap: error: the live view's server (cpp-httplib): ", 0), 0u)
        << serve.output;
    EXPECT_NE(serve.output.find(serve_reason), std::string::npos) << serve.output;

    EXPECT_EQ(Run("info " + kMrm).status, 0);
    const Result render = Run("render " + kMrm + " -o " + Path("a.png"));
    EXPECT_EQ(render.status, 0) << render.output;
    const Result frames = Run(animate + Path("frames/%03d.png"));
    EXPECT_EQ(frames.status, 0) << frames.output;
    EXPECT_TRUE(fs::exists(Path("frames/000.png")));
  }
};

TEST_F(BinaryCopyTest, WithoutModulesOnlyAnimateToVideoAndServeFail) {
  URDFSNAP_REQUIRE_GL();
  ExpectOnlyModuleCommandsFail("urdfsnap-meshes.so is in none of " + Path("bin"),
                               "urdfsnap-video.so is in none of " + Path("bin"),
                               "urdfsnap-serve.so is in none of " + Path("bin"));
}

TEST_F(BinaryCopyTest, BrokenOrSwappedModulesAreOneErrorLine) {
  URDFSNAP_REQUIRE_GL();
  // not a shared object at all, and other modules under these ones' names
  Write("bin/urdfsnap-video.so", "not a shared object\n");
  const fs::path built = fs::path(URDFSNAP_BINARY).parent_path();
  fs::copy_file(built / "urdfsnap-video.so", Path("bin/urdfsnap-serve.so"));
  fs::copy_file(built / "urdfsnap-serve.so", Path("bin/urdfsnap-meshes.so"));
  ExpectOnlyModuleCommandsFail(Path("bin/urdfsnap-meshes.so") + " has no urdfsnap_mesh_module",
                               "cannot load " + Path("bin/urdfsnap-video.so") + " (",
                               Path("bin/urdfsnap-serve.so") + " has no urdfsnap_serve_module");
}

}  // namespace
}  // namespace urdfsnap::cli_test
