// Poses, scenes and draws for the pipeline benchmark.
#include "frame_loop.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>

#include "common/error.h"
#include "common/warnings.h"
#include "timing.h"

namespace urdfsnap::bench {

std::shared_ptr<const model::Robot> LoadRobotFile(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  Warnings warnings;
  try {
    return std::make_shared<const model::Robot>(model::LoadRobot(text.str(), path, warnings));
  } catch (const Error& e) {
    std::fprintf(stderr, "%s\n", e.what());
    std::exit(2);
  }
}

scene::Scene ZeroPoseScene(const std::string& path) {
  const auto robot = LoadRobotFile(path);
  Warnings warnings;
  scene::SceneOptions options;
  options.model_file = path;
  const render::RobotRenderer robot_renderer(robot, options, warnings);
  return robot_renderer.Pose(model::ResolveJointPositions(*robot, {}, true, warnings));
}

std::vector<model::NamedValues> RandomPoses(const model::Robot& robot, int count) {
  std::mt19937 random(42);
  std::uniform_real_distribution<double> angle(-3.0, 3.0);
  std::vector<model::NamedValues> poses(static_cast<std::size_t>(count));
  for (auto& pose : poses) {
    for (const auto& name : robot.MovableJointNames()) pose.emplace_back(name, angle(random));
  }
  return poses;
}

FrameTimes RenderPoses(const render::RobotRenderer& robot, const std::vector<model::NamedValues>& poses,
                       gl::SceneRenderer& renderer, bool with_outputs) {
  FrameTimes times;
  Warnings warnings;
  const image::FrameOutputs all{true, true, true};
  std::vector<double> scene_times, draw_times, output_times;
  for (const auto& pose : poses) {
    const auto t0 = Clock::now();
    const auto positions = model::ResolveJointPositions(robot.robot(), pose, true, warnings);
    const scene::Scene scene = robot.Pose(positions);
    const auto t1 = Clock::now();
    times.last = renderer.Render(scene, scene::OrbitView{}, 640, 480).colour;
    const auto t2 = Clock::now();
    if (with_outputs) renderer.Render(scene, scene::OrbitView{}, 640, 480, all);
    scene_times.push_back(Seconds(t0, t1));
    draw_times.push_back(Seconds(t1, t2));
    output_times.push_back(Seconds(t2, Clock::now()));
    if (times.triangles == 0) {
      for (const auto& item : scene.items) times.triangles += item.mesh->indices.size() / 3;
    }
  }
  times.scene = Median(scene_times);
  times.draw = Median(draw_times);
  if (with_outputs) times.outputs = Median(output_times);
  return times;
}

}  // namespace urdfsnap::bench
