// A camera as the keypoint and COCO files describe it: {"width", "height", "K": [9 numbers,
// row-major], "D": [...], "distortion_model", "pose": [x, y, z, qx, qy, qz, qw]}, so that
// cv2.projectPoints(points_C, 0, 0, K, D) gives the pixels of the image it made.
#pragma once

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include "camera/camera_model.h"

namespace urdfsnap::dataset {

// `camera` with its optical frame at X_FC (metres, in the fixed frame). An image without lens
// distortion is described as ROS describes a distortion-free camera: plumb_bob with five zeros.
nlohmann::ordered_json CameraJson(const camera::CameraModel& camera, const Eigen::Isometry3d& X_FC);

}  // namespace urdfsnap::dataset
