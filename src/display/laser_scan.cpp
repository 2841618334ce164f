// ProjectLaserScan: laser_geometry's projection, written into a packed float32 PointCloud2.
#include "display/laser_scan.h"

#include <cmath>
#include <cstring>

namespace urdfsnap::display {

PointCloud2 ProjectLaserScan(const LaserScan& scan) {
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
    float values[4] = {static_cast<float>(r * std::cos(angle)), static_cast<float>(r * std::sin(angle)), 0.f,
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

}  // namespace urdfsnap::display
