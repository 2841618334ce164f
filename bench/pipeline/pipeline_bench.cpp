// The pipeline benchmark: prints a table with, at 640x480, for the mrm robot (or MODEL), the same
// with RViz's TF display with and without frame names, and for a generated robot of 200,000 mesh
// triangles (heavy_robot.h):
//   - the whole `urdfsnap render` process, model file to PNG on disk (median of N runs),
//   - per frame over 200 poses in one process, through the typed core (render::RobotRenderer, the
//     robot prepared once): joints + FK + posing the scene, draw with 4x MSAA + read back, and the
//     same with the depth and link-label images as well,
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
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "heavy_robot.h"
#include "image/png_writer.h"
#include "model/forward_kinematics.h"
#include "model/joint_values.h"
#include "gl/renderer.h"
#include "render/robot_renderer.h"

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

struct Figures {
  double process = 0;  // whole `urdfsnap render` process, seconds (median)
  double scene = 0;    // per frame: joints + FK + posing the prepared scene
  double draw = 0;     // per frame: draw (4x MSAA) + read back
  double outputs = 0;  // per frame: draw + read back with depth and labels too
  double png = 0;      // per frame: PNG encoding
  double fk = 0;       // forward kinematics of all links
  std::size_t links = 0, triangles = 0;
};

// `tf_args` are the render options that give `tf` (none, "--tf", "--tf --no-tf-names").
Figures Measure(const std::string& binary, const std::string& model_path, int process_runs,
                const urdfsnap::scene::TfOptions& tf = {}, const std::vector<std::string>& tf_args = {}) {
  using namespace urdfsnap;
  Figures figures;
  const std::string out = "/tmp/urdfsnap_bench_" + std::to_string(getpid()) + ".png";

  // whole process, after two warm-up runs fill Mesa's shader cache
  std::vector<std::string> command = {binary, "render", model_path, "-o", out};
  command.insert(command.end(), tf_args.begin(), tf_args.end());
  RunProcess(command);
  RunProcess(command);
  figures.process = MedianTime(process_runs, [&] { RunProcess(command); });
  std::remove(out.c_str());

  // per frame, one process, one context
  Warnings warnings;
  const auto robot_pointer =
      std::make_shared<const model::Robot>(model::LoadRobot(ReadText(model_path), model_path, warnings));
  const model::Robot& robot = *robot_pointer;
  scene::SceneOptions options;
  options.model_file = model_path;
  options.tf = tf;
  const render::RobotRenderer robot_renderer(robot_pointer, options, warnings);
  gl::Renderer renderer(4);
  std::mt19937 random(42);
  std::uniform_real_distribution<double> angle(-3.0, 3.0);
  std::vector<model::NamedValues> poses(200);
  for (auto& pose : poses) {
    for (const auto& name : robot.MovableJointNames()) pose.emplace_back(name, angle(random));
  }
  std::vector<double> scene_times, draw_times, output_times;
  image::Image frame;
  const image::FrameOutputs all{true, true, true};
  for (const auto& pose : poses) {
    const auto t0 = Clock::now();
    const auto positions = model::ResolveJointPositions(robot, pose, true, warnings);
    const scene::Scene scene = robot_renderer.Pose(positions);
    const auto t1 = Clock::now();
    frame = renderer.Render(scene, scene::OrbitView{}, 640, 480).colour;
    const auto t2 = Clock::now();
    renderer.Render(scene, scene::OrbitView{}, 640, 480, all);
    scene_times.push_back(Seconds(t0, t1));
    draw_times.push_back(Seconds(t1, t2));
    output_times.push_back(Seconds(t2, Clock::now()));
    if (figures.triangles == 0) {
      for (const auto& item : scene.items) figures.triangles += item.mesh->indices.size() / 3;
    }
  }
  figures.scene = Median(scene_times);
  figures.draw = Median(draw_times);
  figures.outputs = Median(output_times);
  figures.png = MedianTime(50, [&] { image::EncodePng(frame); });

  // forward kinematics alone
  const auto positions = model::ResolveJointPositions(robot, poses[0], true, warnings);
  std::vector<Eigen::Isometry3d> X_RL;
  const int fk_runs = 1000000;
  const auto t0 = Clock::now();
  for (int i = 0; i < fk_runs; ++i) {
    model::ComputeLinkPoses(robot, positions, X_RL);
    asm volatile("" : : "r"(X_RL.data()) : "memory");
  }
  figures.fk = Seconds(t0, Clock::now()) / fk_runs;
  figures.links = robot.links().size();
  return figures;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string binary = argc > 1 ? argv[1] : URDFSNAP_BINARY;
  const std::string mrm = argc > 2 ? argv[2]
                                   : std::string(URDFSNAP_SOURCE_DIR) +
                                         "/models/mrm_description/urdf/mrm.urdf";
  const std::string heavy_dir = "/tmp/urdfsnap_bench_heavy_" + std::to_string(getpid());
  const std::string heavy = urdfsnap::bench::WriteHeavyRobot(heavy_dir, 200000);
  urdfsnap::scene::TfOptions tf;
  tf.enabled = true;
  const Figures a = Measure(binary, mrm, 20);
  const Figures t = Measure(binary, mrm, 20, tf, {"--tf"});
  tf.show_names = false;
  const Figures u = Measure(binary, mrm, 20, tf, {"--tf", "--no-tf-names"});
  const Figures b = Measure(binary, heavy, 10);
  std::filesystem::remove_all(heavy_dir);

  std::printf("| measurement, 640x480, median                 | mrm          | mrm --tf     | --tf, no names | heavy (meshes) |\n");
  std::printf("|----------------------------------------------|--------------|--------------|----------------|----------------|\n");
  std::printf("| triangles drawn                              | %12zu | %12zu | %14zu | %14zu |\n", a.triangles, t.triangles, u.triangles, b.triangles);
  std::printf("| whole `urdfsnap render` process, URDF → PNG  | %9.1f ms | %9.1f ms | %11.1f ms | %11.1f ms |\n", a.process * 1e3, t.process * 1e3, u.process * 1e3, b.process * 1e3);
  std::printf("| per frame: joints + FK + posing the scene    | %9.4f ms | %9.4f ms | %11.4f ms | %11.4f ms |\n", a.scene * 1e3, t.scene * 1e3, u.scene * 1e3, b.scene * 1e3);
  std::printf("| per frame: draw (4x MSAA) + read back        | %9.3f ms | %9.3f ms | %11.3f ms | %11.3f ms |\n", a.draw * 1e3, t.draw * 1e3, u.draw * 1e3, b.draw * 1e3);
  std::printf("| per frame: the same + depth + labels         | %9.3f ms | %9.3f ms | %11.3f ms | %11.3f ms |\n", a.outputs * 1e3, t.outputs * 1e3, u.outputs * 1e3, b.outputs * 1e3);
  std::printf("| per frame: PNG encoding                      | %9.3f ms | %9.3f ms | %11.3f ms | %11.3f ms |\n", a.png * 1e3, t.png * 1e3, u.png * 1e3, b.png * 1e3);
  std::printf("| FK alone, all links (%zu / %zu)                 | %9.3f µs | %9.3f µs | %11.3f µs | %11.3f µs |\n", a.links, b.links, a.fk * 1e6, t.fk * 1e6, u.fk * 1e6, b.fk * 1e6);
  return 0;
}
