// The centre of a posed robot's geometry, which dataset cameras look at: the bounding box of every
// drawn part's mesh box, placed by the link poses.
#pragma once

#include <array>
#include <vector>

#include <Eigen/Geometry>

#include "scene/robot_scene.h"

namespace urdfsnap::dataset {

class RobotBounds {
 public:
  // The corners of each part's mesh bounds in its link frame, found once.
  explicit RobotBounds(const scene::RobotScene& scene);

  // The bounding box of every part for link poses X_RL (root frame, metres); the link origins' box
  // for a robot with no geometry.
  Eigen::AlignedBox3d Box(const std::vector<Eigen::Isometry3d>& X_RL) const;

 private:
  struct Part {
    int link;
    std::array<Eigen::Vector3d, 8> corners_L;
  };
  std::vector<Part> parts_;
};

}  // namespace urdfsnap::dataset
