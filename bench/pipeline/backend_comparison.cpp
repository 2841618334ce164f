// The GL backends side by side: context creation, per-frame draw and the whole render process.
#include "backend_comparison.h"

#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "common/error.h"
#include "frame_loop.h"
#include "gl/backend.h"
#include "gl/gl_context.h"
#include "timing.h"

namespace urdfsnap::bench {

namespace {

struct BackendFigures {
  double first_context = 0, next_context = 0, draw = 0, process = 0;  // seconds
  std::string description;
};

}  // namespace

int MeasureBackend(const std::string& backend_name, const std::string& model_path,
                   const std::string& figures_path) {
  try {
    const gl::Backend backend = gl::ParseBackend(backend_name);
    const auto t0 = Clock::now();
    std::string description = gl::CreateGlContext(backend)->description();
    const double first = Seconds(t0, Clock::now());
    const double next = MedianTime(10, [&] { gl::CreateGlContext(backend); });

    const auto robot = LoadRobotFile(model_path);
    scene::SceneOptions options;
    options.model_file = model_path;
    Warnings warnings;
    const render::RobotRenderer robot_renderer(robot, options, warnings);
    gl::SceneRenderer renderer(4, {backend});
    const FrameTimes frames = RenderPoses(robot_renderer, RandomPoses(*robot, 200), renderer, false);
    std::ofstream(figures_path) << first << " " << next << " " << frames.draw << " " << description << "\n";
    return 0;
  } catch (const Error& e) {
    std::fprintf(stderr, "%s: %s\n", backend_name.c_str(), e.what());
    return 2;
  }
}

void PrintBackendComparison(const std::string& self, const std::string& binary, const std::string& model) {
  std::vector<std::pair<std::string, BackendFigures>> columns;
  const std::string out = "/tmp/urdfsnap_bench_backend_" + std::to_string(getpid()) + ".png";
  const std::string figures_path = out + ".txt";
  for (gl::Backend backend : gl::CompiledInBackends()) {
    const std::string name(gl::BackendName(backend));
    BackendFigures f;
    if (!TryProcess({self, kMeasureBackendOption, name, model, figures_path})) {
      std::printf("(no figures for %s: it cannot make a context here)\n", name.c_str());
      continue;
    }
    std::ifstream line(figures_path);
    line >> f.first_context >> f.next_context >> f.draw;
    std::getline(line >> std::ws, f.description);
    // whole process, after two warm-up runs fill Mesa's shader cache
    const std::vector<std::string> command = {binary, "render", model, "-o", out};
    const std::vector<std::string> environment = {"URDFSNAP_GL_BACKEND=" + name};
    RunProcess(command, environment);
    RunProcess(command, environment);
    f.process = MedianTime(20, [&] { RunProcess(command, environment); });
    columns.emplace_back(name, f);
  }
  std::remove(out.c_str());
  std::remove(figures_path.c_str());

  std::printf("\n| GL backends, mrm at 640x480, 4x MSAA, median          |");
  for (const auto& [name, f] : columns) std::printf(" %12s |", name.c_str());
  std::printf("\n|-------------------------------------------------------|");
  for (size_t i = 0; i < columns.size(); ++i) std::printf("--------------|");
  const std::pair<const char*, double BackendFigures::*> rows[] = {
      {"first context in a process, library load included", &BackendFigures::first_context},
      {"each later context", &BackendFigures::next_context},
      {"per frame: draw + read back", &BackendFigures::draw},
      {"whole `urdfsnap render` process, URDF -> PNG", &BackendFigures::process}};
  for (const auto& [label, field] : rows) {
    std::printf("\n| %-53s |", label);
    for (const auto& [name, f] : columns) std::printf(" %9.2f ms |", f.*field * 1e3);
  }
  std::printf("\n");
  for (const auto& [name, f] : columns) std::printf("%s: %s\n", name.c_str(), f.description.c_str());
}

}  // namespace urdfsnap::bench
