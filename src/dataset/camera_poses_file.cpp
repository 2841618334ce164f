// ParseCameraPoses: line by line, seven numbers each, through the one number grammar.
#include "dataset/camera_poses_file.h"

#include <algorithm>

#include "common/error.h"
#include "common/file_reading.h"
#include "common/number_text.h"

namespace urdfsnap::dataset {

std::vector<Eigen::Isometry3d> ParseCameraPoses(std::string_view text, const std::string& path) {
  std::vector<Eigen::Isometry3d> poses;
  int line_number = 0;
  size_t start = 0;
  while (start < text.size()) {
    size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    std::string line(text.substr(start, end - start));
    start = end + 1;
    ++line_number;
    std::replace(line.begin(), line.end(), ',', ' ');
    std::replace(line.begin(), line.end(), '\r', ' ');
    const size_t first = line.find_first_not_of(" \t");
    if (first == std::string::npos || line[first] == '#') continue;
    const SourceLocation where{path, line_number};
    double n[7];
    if (!ParseNumbers(line, 7, n)) {
      throw Error(where, "expected a camera pose: seven numbers X Y Z QX QY QZ QW");
    }
    const Eigen::Quaterniond q(n[6], n[3], n[4], n[5]);
    if (q.norm() < 1e-9) throw Error(where, "the quaternion QX QY QZ QW is zero");
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.translation() = Eigen::Vector3d(n[0], n[1], n[2]);
    pose.linear() = q.normalized().toRotationMatrix();
    poses.push_back(pose);
  }
  if (poses.empty()) throw Error(SourceLocation{path, 0}, "no camera pose in the file");
  return poses;
}

std::vector<Eigen::Isometry3d> ReadCameraPoses(const std::string& path) {
  try {
    return ParseCameraPoses(ReadFileBounded(path), path);
  } catch (const FileReadError& e) {
    throw Error(SourceLocation{path, 0}, std::string("cannot read the camera poses: ") + e.what());
  }
}

}  // namespace urdfsnap::dataset
