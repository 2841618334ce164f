// ProjectLaserScan: laser_geometry's projection, written into a packed float32 PointCloud2, and
// its high-fidelity form moving each beam by the frame's motion during the scan.
#include "display/laser_scan.h"

#include <cmath>
#include <cstring>

namespace urdfsnap::display {

namespace {

// projectLaser_ with each kept beam's point moved by `place(i, point)`.
template <typename Place>
PointCloud2 Project(const LaserScan& scan, const Place& place) {
  constexpr std::uint8_t kFloat32 = 7;
  PointCloud2 cloud;
  cloud.frame_id = scan.frame_id;
  cloud.stamp_ns = scan.stamp_ns;
  const bool with_intensity = !scan.intensities.empty();
  cloud.fields = {{"x", 0, kFloat32, 1}, {"y", 4, kFloat32, 1}, {"z", 8, kFloat32, 1}};
  if (with_intensity) cloud.fields.push_back({"intensity", 12, kFloat32, 1});
  cloud.point_step = with_intensity ? 16 : 12;
  cloud.height = 1;
  cloud.data.reserve(scan.ranges.size() * cloud.point_step);
  for (std::size_t i = 0; i < scan.ranges.size(); ++i) {
    const float r = scan.ranges[i];
    if (!(r < scan.range_max && r >= scan.range_min)) continue;
    const double angle = static_cast<double>(scan.angle_min) + static_cast<double>(i) * scan.angle_increment;
    const Eigen::Vector3d point = place(i, Eigen::Vector3d(r * std::cos(angle), r * std::sin(angle), 0));
    float values[4] = {static_cast<float>(point.x()), static_cast<float>(point.y()), static_cast<float>(point.z()),
                       i < scan.intensities.size() ? scan.intensities[i] : 0.f};
    const std::size_t at = cloud.data.size();
    cloud.data.resize(at + cloud.point_step);
    std::memcpy(cloud.data.data() + at, values, cloud.point_step);
    ++cloud.width;
  }
  cloud.row_step = cloud.width * cloud.point_step;
  cloud.is_dense = true;
  return cloud;
}

}  // namespace

PointCloud2 ProjectLaserScan(const LaserScan& scan) {
  return Project(scan, [](std::size_t, const Eigen::Vector3d& p) { return p; });
}

PointCloud2 ProjectLaserScan(const LaserScan& scan, const Eigen::Isometry3d& X_start, const Eigen::Isometry3d& X_end) {
  const Eigen::Quaterniond q_start(X_start.rotation()), q_end(X_end.rotation());
  const double last = scan.ranges.size() > 1 ? static_cast<double>(scan.ranges.size() - 1) : 1.0;
  PointCloud2 cloud = Project(scan, [&](std::size_t i, const Eigen::Vector3d& p) {
    const double ratio = static_cast<double>(i) / last;
    const Eigen::Vector3d translation = (1 - ratio) * X_start.translation() + ratio * X_end.translation();
    return Eigen::Vector3d(q_start.slerp(ratio, q_end) * p + translation);
  });
  cloud.frame_id.clear();
  return cloud;
}

std::int64_t LastBeamStamp(const LaserScan& scan) {
  const double span_ns = static_cast<double>(scan.ranges.size()) * scan.time_increment * 1e9;
  // a time_increment that is not a number or spans centuries (a hostile scan) moves nothing
  if (scan.stamp_ns == 0 || scan.ranges.size() < 2 || !(std::abs(span_ns) < 1e18)) return scan.stamp_ns;
  return scan.stamp_ns + std::llround(static_cast<double>(scan.ranges.size() - 1) * scan.time_increment * 1e9);
}

}  // namespace urdfsnap::display
