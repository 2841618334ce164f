// RViz's Path display (path_display.cpp): a nav_msgs/Path as a line through its pose positions,
// 1-pixel GL lines or billboard ribbons, moved by Offset.
#pragma once

#include "display/display_settings.h"
#include "display/pose_list_display.h"

namespace urdfsnap::display {

class PathDisplay : public PoseListDisplay {
 public:
  PathDisplay(std::string topic, PathSettings settings);

 private:
  void DrawPoses(const PoseList& poses, const Eigen::Isometry3d& X_FH, scene::Scene& scene) const override;
  PathSettings settings_;
};

}  // namespace urdfsnap::display
