// The benchmark's frame loop through the typed core: random poses of a robot prepared once
// (render::RobotRenderer), each posed (joints, FK, posing the scene) and drawn (read back), timed
// separately.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "gl/scene_renderer.h"
#include "image/image.h"
#include "model/joint_values.h"
#include "model/robot.h"
#include "render/robot_renderer.h"

namespace urdfsnap::bench {

// The robot of the URDF file at `path`. Exits the benchmark when it cannot be read.
std::shared_ptr<const model::Robot> LoadRobotFile(const std::string& path);

// The robot of the URDF file at `path` at its zero pose (joint_state_publisher's defaults), as a
// scene: prepared with render::RobotRenderer and posed once. Exits like LoadRobotFile.
scene::Scene ZeroPoseScene(const std::string& path);

// `count` poses with every movable joint at a random angle in [-3, 3] (seeded: the same each run).
std::vector<model::NamedValues> RandomPoses(const model::Robot& robot, int count);

struct FrameTimes {
  double scene = 0;           // median per frame: joints + FK + posing the scene, seconds
  double draw = 0;            // median per frame: draw + read back of the colour image, seconds
  double outputs = 0;         // median per frame: the same with depth and labels too (when asked)
  std::size_t triangles = 0;  // drawn in the first frame
  image::Image last;          // the last colour image
};

// Renders each pose at 640x480 from RViz's default view with `renderer`; with `with_outputs`,
// each pose a second time with the depth and label images as well.
FrameTimes RenderPoses(const render::RobotRenderer& robot, const std::vector<model::NamedValues>& poses,
                       gl::SceneRenderer& renderer, bool with_outputs);

}  // namespace urdfsnap::bench
