// The camera poses a dataset cycles through (`dataset --camera-poses FILE`): a text file with one
// pose of the camera's optical frame (z forward, x right, y down) per line, seven numbers
// "X Y Z QX QY QZ QW" (metres; the quaternion normalised, as tf2 does), separated by spaces or
// commas (so `--camera-pose`'s "X,Y,Z,QX,QY,QZ,QW" works too). Blank lines and lines starting with
// '#' are skipped.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Geometry>

namespace urdfsnap::dataset {

// The poses of `text`, read from the file `path` (for messages). Throws urdfsnap::Error located at
// the line for anything but seven finite numbers with a non-zero quaternion, or a file with no pose.
std::vector<Eigen::Isometry3d> ParseCameraPoses(std::string_view text, const std::string& path);

// ParseCameraPoses of the file at `path`; throws urdfsnap::Error for a file that cannot be read.
std::vector<Eigen::Isometry3d> ReadCameraPoses(const std::string& path);

}  // namespace urdfsnap::dataset
