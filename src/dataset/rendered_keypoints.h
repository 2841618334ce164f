// Keypoints of a frame just rendered by a render::RobotRenderer: the camera it was seen through
// (a calibrated one, or the orbit view as a camera) placed for the frame's pose, and its frames'
// keypoints against the frame's own depth and label images.
#pragma once

#include <string>
#include <vector>

#include "dataset/frame_keypoints.h"
#include "render/robot_renderer.h"

namespace urdfsnap::dataset {

// The keypoints file text (KeypointsJson, indented by `indent`) of `frame`, rendered from `robot` at
// `positions` through `camera`; `frame` must hold its depth and label images.
std::string RenderedKeypointsJson(const render::RobotRenderer& robot, const std::vector<double>& positions,
                                  const render::CameraSettings& camera, const image::Frame& frame, int indent = 2);

// Keypoints and the camera pose X_FC (in the fixed frame) of the same.
struct RenderedKeypoints {
  Eigen::Isometry3d X_FC;
  std::vector<FrameKeypoint> keypoints;
};
RenderedKeypoints KeypointsOfFrame(const render::RobotRenderer& robot, const std::vector<double>& positions,
                                   const render::CameraSettings& camera, const image::Frame& frame);

}  // namespace urdfsnap::dataset
