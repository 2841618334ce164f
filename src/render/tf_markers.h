// RViz's TF display as draw items: per frame its axes, and an arrow from each frame to its parent
// (src/rviz/default_plugin/tf_display.cpp, ogre_helpers/axes.cpp, ogre_helpers/arrow.cpp).
#pragma once

#include <vector>

#include <Eigen/Geometry>

#include "model/robot.h"
#include "render/scene.h"
#include "render/scene_builder.h"

namespace urdfsnap::render {

// Adds the axes and parent arrows of every link frame. X_FL: link poses in the fixed frame.
void AddTfMarkers(const model::Robot& robot, const std::vector<Eigen::Isometry3d>& X_FL,
                  const TfOptions& options, Scene& scene);

}  // namespace urdfsnap::render
