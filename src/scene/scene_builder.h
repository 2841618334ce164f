// Turns a posed robot into a Scene, the way RViz's RobotModel and Grid displays would show it:
// which shapes are visible, where (in the fixed frame), and in which colour. GL-free.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "common/warnings.h"
#include "model/robot.h"
#include "scene/grid.h"
#include "scene/scene.h"
#include "scene/tf_markers.h"

namespace urdfsnap::scene {

// What the displays show, with RViz's defaults (robot_model_display.cpp L60-86,
// visualization_manager.cpp L172-179).
struct SceneOptions {
  std::string fixed_frame;        // a link name; "" means the root link
  // where mesh URIs are resolved from: relative paths and package.xml folders around this file,
  // and the --package PKG=DIR map (see geometry/mesh_uri.h)
  std::string model_file;
  std::map<std::string, std::string> packages;
  bool allow_missing_meshes = false;   // a mesh that cannot be found is a warning, not an error
  bool show_visual = true;        // RobotModel "Visual Enabled"
  bool show_collision = false;    // RobotModel "Collision Enabled"
  double alpha = 1.0;             // RobotModel "Alpha", multiplies every material's alpha
  Eigen::Vector3f background{48 / 255.f, 48 / 255.f, 48 / 255.f};
  GridOptions grid;
  TfOptions tf;
};

// Builds the scene for link poses X_RL (one per robot.links(), in the root frame R, as
// model::ComputeLinkPoses returns them). Throws urdfsnap::Error for an unknown fixed frame.
Scene BuildScene(const model::Robot& robot, const std::vector<Eigen::Isometry3d>& X_RL,
                 const SceneOptions& options, Warnings& warnings);

}  // namespace urdfsnap::scene
