// RViz's TF display as draw items: per frame its axes, its name, and an arrow from each frame to its
// parent (src/rviz/default_plugin/tf_display.cpp, ogre_helpers/axes.cpp, ogre_helpers/arrow.cpp,
// ogre_helpers/movable_text.cpp).
#pragma once

#include <vector>

#include <Eigen/Geometry>

#include "model/robot.h"
#include "scene/scene.h"

namespace urdfsnap::scene {

// The TF display's properties with RViz's defaults (tf_display.cpp L164-191); off unless asked.
struct TfOptions {
  bool enabled = false;
  bool show_names = true;
  bool show_axes = true;
  bool show_arrows = true;
  double marker_scale = 1.0;
};

// Adds the axes, names and parent arrows of every link frame, as `options` ask. X_FL: link poses in
// the fixed frame. Throws urdfsnap::Error when names are asked for and Liberation Sans is missing.
void AddTfMarkers(const model::Robot& robot, const std::vector<Eigen::Isometry3d>& X_FL,
                  const TfOptions& options, Scene& scene);

}  // namespace urdfsnap::scene
