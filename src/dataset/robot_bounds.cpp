// RobotBounds: mesh boxes once, eight corners per part per pose.
#include "dataset/robot_bounds.h"

namespace urdfsnap::dataset {

RobotBounds::RobotBounds(const scene::RobotScene& scene) {
  for (const scene::LinkPart& part : scene.parts()) {
    if (!part.mesh || part.mesh->positions.empty()) continue;
    Eigen::AlignedBox3d box;
    for (const Eigen::Vector3f& p : part.mesh->positions) box.extend(p.cast<double>());
    Part placed{part.link, {}};
    for (int i = 0; i < 8; ++i) placed.corners_L[i] = part.X_LG * box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(i));
    parts_.push_back(placed);
  }
}

Eigen::AlignedBox3d RobotBounds::Box(const std::vector<Eigen::Isometry3d>& X_RL) const {
  Eigen::AlignedBox3d box;
  for (const Part& part : parts_) {
    for (const Eigen::Vector3d& corner : part.corners_L) box.extend(X_RL[part.link] * corner);
  }
  if (box.isEmpty()) {
    for (const Eigen::Isometry3d& X : X_RL) box.extend(X.translation());
  }
  return box;
}

}  // namespace urdfsnap::dataset
