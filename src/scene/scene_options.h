// What the displays show, with RViz's defaults: the RobotModel display (visual, collision, alpha),
// the global options (fixed frame, background), the Grid and the TF display; and where the model's
// files are found. Filled from flags, suite files and `.rviz` files (src/render/).
#pragma once

#include <map>
#include <string>

#include <Eigen/Core>

#include "scene/grid.h"
#include "scene/tf_markers.h"

namespace urdfsnap::scene {

// robot_model_display.cpp L60-86, visualization_manager.cpp L172-179.
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
  // RobotModel "Links" > <link> > "Alpha" by link name, 0 to 1, 1 for links not named: multiplies
  // the alpha of that link's materials as the robot alpha does (robot_link.cpp updateAlpha:
  // robot alpha * material alpha * link alpha)
  std::map<std::string, double> link_alpha;
  Eigen::Vector3f background{48 / 255.f, 48 / 255.f, 48 / 255.f};
  GridOptions grid;
  TfOptions tf;

  bool operator==(const SceneOptions&) const = default;
};

}  // namespace urdfsnap::scene
