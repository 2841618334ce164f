// Per-frame cost of drawing a published robot through the typed core, for robots_bench.sh: the
// robot (a URDF, xacro already expanded) prepared once, the view fitted to it, then a turntable of
// FRAMES yaw steps at 640x480 with 4x MSAA, each frame drawn and read back (render::RobotRenderer
// and gl::SceneRenderer, no encoding). Prints one line: "triangles T draw_ms D cpu_ms C" with the median
// wall time per frame and the process CPU time (all threads) per frame, so a loaded machine shows
// in the gap between them. llvmpipe's thread count is its own default (one per core) unless
// LP_NUM_THREADS says otherwise.
// usage: urdfsnap_robot_frames MODEL.urdf [PKG=DIR...] [--frames N]
#include <sys/resource.h>

#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <string>
#include <vector>

#include "../pipeline/frame_loop.h"
#include "../pipeline/timing.h"
#include "common/error.h"
#include "common/warnings.h"
#include "gl/scene_renderer.h"
#include "model/joint_values.h"
#include "render/robot_renderer.h"

namespace {

using namespace urdfsnap;

double CpuSeconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const auto seconds = [](const timeval& t) { return static_cast<double>(t.tv_sec) + t.tv_usec / 1e6; };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

int Run(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: urdfsnap_robot_frames MODEL.urdf [PKG=DIR...] [--frames N]\n");
    return 2;
  }
  scene::SceneOptions options;
  options.model_file = argv[1];
  int frames = 60;
  for (int i = 2; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--frames" && i + 1 < argc) {
      frames = std::atoi(argv[++i]);
    } else if (const auto eq = arg.find('='); eq != std::string::npos) {
      options.packages[arg.substr(0, eq)] = arg.substr(eq + 1);
    } else {
      std::fprintf(stderr, "urdfsnap_robot_frames: unknown argument %s\n", arg.c_str());
      return 2;
    }
  }
  Warnings warnings;
  const auto robot = bench::LoadRobotFile(options.model_file);
  const render::RobotRenderer renderer(robot, options, warnings);
  const std::vector<double> positions = model::ResolveJointPositions(*robot, {}, true, warnings);
  const render::ImageSize size{640, 480};
  const auto pose = [&](int) { return positions; };
  const scene::OrbitView fitted = renderer.FitView(render::Fit::kFit, {}, scene::OrbitView{}, size, 1, pose);
  gl::SceneRenderer gl(4);
  renderer.Render(gl, positions, fitted, size);   // uploads the meshes and compiles the shaders
  std::vector<double> times;
  const double cpu0 = CpuSeconds();
  for (int k = 0; k < frames; ++k) {
    scene::OrbitView view = fitted;
    view.yaw += 2 * std::numbers::pi * k / frames;
    const auto t0 = bench::Clock::now();
    renderer.Render(gl, positions, view, size);
    times.push_back(bench::Seconds(t0, bench::Clock::now()));
  }
  const double cpu = (CpuSeconds() - cpu0) / frames;
  std::printf("triangles %zu draw_ms %.2f cpu_ms %.2f\n", renderer.scene().triangle_count(),
              1000 * bench::Median(times), 1000 * cpu);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return Run(argc, argv);
  } catch (const urdfsnap::Error& e) {
    std::fprintf(stderr, "urdfsnap_robot_frames: %s\n", e.what());
    return 2;
  }
}
