// The pipeline benchmark of the core issue: prints a table with, for the mrm robot at 640x480,
//   - the whole `urdfsnap render` process, model file to PNG on disk (median of N runs),
//   - per frame over 200 poses in one process: FK + scene, draw with 4x MSAA + read back,
//   - PNG encoding of one frame,
//   - forward kinematics alone for all links.
// usage: urdfsnap_pipeline_bench [URDFSNAP_BINARY [MODEL]]
// Timings only: no test asserts on them.
#include <sys/wait.h>
#include <spawn.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <functional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "image/png_writer.h"
#include "model/forward_kinematics.h"
#include "model/joint_values.h"
#include "render/renderer.h"
#include "render/scene_builder.h"

extern char** environ;

namespace {

using Clock = std::chrono::steady_clock;

double Seconds(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

double Median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// Median wall time of `runs` calls of fn (each timed on its own).
double MedianTime(int runs, const std::function<void()>& fn) {
  std::vector<double> times;
  for (int i = 0; i < runs; ++i) {
    const auto t0 = Clock::now();
    fn();
    times.push_back(Seconds(t0, Clock::now()));
  }
  return Median(times);
}

void RunProcess(std::vector<std::string> args) {
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid;
  if (posix_spawn(&pid, argv[0], nullptr, nullptr, argv.data(), environ) != 0) {
    std::fprintf(stderr, "cannot run %s\n", argv[0]);
    std::exit(2);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::fprintf(stderr, "%s failed\n", argv[0]);
    std::exit(2);
  }
}

std::string ReadText(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

int main(int argc, char** argv) {
  using namespace urdfsnap;
  const std::string binary = argc > 1 ? argv[1] : URDFSNAP_BINARY;
  const std::string model_path =
      argc > 2 ? argv[2] : std::string(URDFSNAP_SOURCE_DIR) + "/models/mrm_description/urdf/mrm.urdf";
  const std::string out = "/tmp/urdfsnap_bench_" + std::to_string(getpid()) + ".png";

  // whole process, after two warm-up runs fill Mesa's shader cache
  const std::vector<std::string> command = {binary, "render", model_path, "-o", out};
  RunProcess(command);
  RunProcess(command);
  const double process = MedianTime(20, [&] { RunProcess(command); });
  std::remove(out.c_str());

  // per frame, one process, one context
  Warnings warnings;
  const model::Robot robot = model::LoadRobot(ReadText(model_path), model_path, warnings);
  render::Renderer renderer(4);
  std::mt19937 random(42);
  std::uniform_real_distribution<double> angle(-3.0, 3.0);
  std::vector<model::NamedValues> poses(200);
  for (auto& pose : poses) {
    for (const auto& name : robot.MovableJointNames()) pose.emplace_back(name, angle(random));
  }
  std::vector<double> scene_times, draw_times;
  image::Image frame;
  for (const auto& pose : poses) {
    const auto t0 = Clock::now();
    const auto positions = model::ResolveJointPositions(robot, pose, true, warnings);
    const render::Scene scene =
        render::BuildScene(robot, model::ComputeLinkPoses(robot, positions), {}, warnings);
    const auto t1 = Clock::now();
    frame = renderer.Render(scene, render::OrbitView{}, 640, 480);
    scene_times.push_back(Seconds(t0, t1));
    draw_times.push_back(Seconds(t1, Clock::now()));
  }
  const double png = MedianTime(50, [&] { image::EncodePng(frame); });

  // forward kinematics alone
  const auto positions = model::ResolveJointPositions(robot, poses[0], true, warnings);
  std::vector<Eigen::Isometry3d> X_RL;
  const int fk_runs = 1000000;
  const auto t0 = Clock::now();
  for (int i = 0; i < fk_runs; ++i) {
    model::ComputeLinkPoses(robot, positions, X_RL);
    asm volatile("" : : "r"(X_RL.data()) : "memory");
  }
  const double fk = Seconds(t0, Clock::now()) / fk_runs;

  std::printf("| measurement (mrm, 640x480)                  | median      |\n");
  std::printf("|---------------------------------------------|-------------|\n");
  std::printf("| whole `urdfsnap render` process, URDF → PNG | %8.1f ms |\n", process * 1e3);
  std::printf("| per frame: joints + FK + scene building     | %8.4f ms |\n", Median(scene_times) * 1e3);
  std::printf("| per frame: draw (4x MSAA) + read back       | %8.3f ms |\n", Median(draw_times) * 1e3);
  std::printf("| per frame: PNG encoding                     | %8.3f ms |\n", png * 1e3);
  std::printf("| FK alone, all %zu links                      | %8.3f µs |\n", robot.links().size(), fk * 1e6);
  return 0;
}
