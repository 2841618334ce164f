// RViz's PoseArray display (pose_array_display.cpp): each pose of a geometry_msgs/PoseArray as a
// flat line arrow, a 3D arrow or axes.
#pragma once

#include "display/display_settings.h"
#include "display/pose_list_display.h"

namespace urdfsnap::display {

class PoseArrayDisplay : public PoseListDisplay {
 public:
  PoseArrayDisplay(std::string topic, PoseArraySettings settings);

 private:
  void DrawPoses(const PoseList& poses, const Eigen::Isometry3d& X_FH, scene::Scene& scene) const override;
  PoseArraySettings settings_;
};

}  // namespace urdfsnap::display
