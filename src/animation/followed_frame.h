// RViz's Target Frame (the Orbit view's, set by --follow or a .rviz file): the view's focal point
// is relative to a frame's origin, so the camera travels with a moving base or a tool while
// keeping its yaw and pitch (RViz's FramePositionTrackingViewController follows the position
// only). The frame is a link of the robot, or with a bag any frame its TF connects to the robot.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "common/warnings.h"
#include "motion/tf_display_frames.h"
#include "render/robot_renderer.h"

namespace urdfsnap::animation {

class FollowedFrame {
 public:
  // `robot` is kept by reference. `tf`: the bag's frames, when there is a bag. Throws
  // urdfsnap::Error "--follow 'x': ..." for a frame that is neither a link nor one of tf's.
  FollowedFrame(const render::RobotRenderer& robot, const std::string& frame,
                std::optional<motion::TfDisplayFrames> tf);

  // Whether the frame is a link of the robot (else a frame of the bag's TF).
  bool is_link() const { return index_ < robot_.robot().links().size(); }

  // The frame's origin in the scene for joint `positions` with the fixed link placed at X_SF,
  // at trajectory time `t` (used for a frame of the bag's TF).
  Eigen::Vector3d Origin(const std::vector<double>& positions, const Eigen::Isometry3d& X_SF, double t,
                         Warnings& warnings) const;

 private:
  const render::RobotRenderer& robot_;
  std::optional<motion::TfDisplayFrames> tf_;
  std::size_t index_ = 0;   // in the robot's links, then tf_'s other frames
};

}  // namespace urdfsnap::animation
