// The pipeline benchmark: prints a table with, at 640x480, for the mrm robot (or MODEL), the same
// with RViz's TF display with and without frame names, and for a generated robot of 200,000 mesh
// triangles (heavy_robot.h):
//   - the whole `urdfsnap render` process, model file to PNG on disk (median of N runs),
//   - per frame over 200 poses in one process, through the typed core (render::RobotRenderer, the
//     robot prepared once): joints + FK + posing the scene, draw with 4x MSAA + read back, and the
//     same with the depth and link-label images as well,
//   - PNG encoding of one frame,
//   - forward kinematics alone for all links;
// then the GL backends side by side (backend_comparison.h): context creation, per-frame draw and
// the whole process, for each compiled-in backend.
// usage: urdfsnap_pipeline_bench [URDFSNAP_BINARY [MODEL]]
// Timings only: no test asserts on them.
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "backend_comparison.h"
#include "frame_loop.h"
#include "heavy_robot.h"
#include "image/png_writer.h"
#include "model/forward_kinematics.h"
#include "timing.h"

namespace {

using namespace urdfsnap::bench;

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
  const auto robot_pointer = LoadRobotFile(model_path);
  const model::Robot& robot = *robot_pointer;
  scene::SceneOptions options;
  options.model_file = model_path;
  options.tf = tf;
  const render::RobotRenderer robot_renderer(robot_pointer, options, warnings);
  gl::SceneRenderer renderer(4);
  const std::vector<model::NamedValues> poses = RandomPoses(robot, 200);
  const FrameTimes frames = RenderPoses(robot_renderer, poses, renderer, true);
  figures.scene = frames.scene;
  figures.draw = frames.draw;
  figures.outputs = frames.outputs;
  figures.triangles = frames.triangles;
  figures.png = MedianTime(50, [&] { image::EncodePng(frames.last); });

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
  if (argc == 5 && std::string(argv[1]) == urdfsnap::bench::kMeasureBackendOption) {
    return urdfsnap::bench::MeasureBackend(argv[2], argv[3], argv[4]);
  }
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
  urdfsnap::bench::PrintBackendComparison(std::filesystem::read_symlink("/proc/self/exe"), binary, mrm);
  return 0;
}
