// A camera's calibration as ROS stores it: the file ROS's camera_calibration writes (image_width,
// image_height, camera_matrix, distortion_model, distortion_coefficients, rectification_matrix,
// projection_matrix, each matrix as {rows, cols, data}) or a sensor_msgs/CameraInfo message as
// `ros2 topic echo` (width, height, k, d, r, p) or `rostopic echo` (K, D, R, P) prints it.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "camera/distortion.h"
#include "camera/pinhole.h"

namespace urdfsnap::camera {

struct CameraInfo {
  int width = 0;                      // pixels
  int height = 0;
  Eigen::Matrix3d K = Eigen::Matrix3d::Zero();          // raw image intrinsics, row-major as given
  std::string distortion_model;       // as written ("plumb_bob", "rational_polynomial", "")
  std::vector<double> D;              // as written
  Distortion distortion;              // D for distortion_model, checked
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();      // rectification rotation (stereo)
  Eigen::Matrix<double, 3, 4> P = Eigen::Matrix<double, 3, 4>::Zero();  // rectified projection
  std::string frame_id;               // header.frame_id of a message, "" for a calibration file

  // K's focal lengths and principal point (the raw, distorted image's).
  Intrinsics RawIntrinsics() const;
  // P's (the rectified image's, which RViz's Camera display draws); K's when P is all zero, as an
  // uncalibrated camera publishes it.
  Intrinsics RectifiedIntrinsics() const;
};

// Checks a CameraInfo made from a sensor_msgs/CameraInfo message (`where` names it) as
// ParseCameraInfo checks a file, and fills in `distortion` from distortion_model and D. Throws
// urdfsnap::Error "WHERE: ..." for a size outside 1 to kMaxImageSide, an unsupported distortion
// model or coefficient count, or a non-positive focal length.
void CheckCameraInfoMessage(CameraInfo& info, const std::string& where);

// Reads the CameraInfo file at `path`. Throws urdfsnap::Error "PATH:LINE: ..." naming the key for
// an unreadable file, bad YAML, a missing or malformed size or matrix, a non-positive focal
// length, an unsupported distortion model or a coefficient count that does not fit it.
CameraInfo ReadCameraInfo(const std::string& path);

// ReadCameraInfo for text already read; `path` names it in messages.
CameraInfo ParseCameraInfo(std::string_view text, const std::string& path);

}  // namespace urdfsnap::camera
