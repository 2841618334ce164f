// The keypoints file `render --keypoints FILE.json` writes:
//   {"camera": CameraJson, "frames": [{"name", "kind": "link"|"joint", "u", "v", "depth",
//    "in_image", "visible"}, ...]}
// (u, v) are OpenCV's projectPoints pixel coordinates (null behind the camera), depth metres along
// the optical axis. Others may add keys; these are never renamed.
#pragma once

#include <string>
#include <vector>

#include "dataset/frame_keypoints.h"

namespace urdfsnap::dataset {

// The file's text (JSON indented by `indent` spaces, or on one line for -1; a final newline) for
// `keypoints` seen by `camera` at X_FC in the fixed frame.
std::string KeypointsJson(const camera::CameraModel& camera, const Eigen::Isometry3d& X_FC,
                          const std::vector<FrameKeypoint>& keypoints, int indent = 2);

}  // namespace urdfsnap::dataset
