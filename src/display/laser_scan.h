// A LaserScan as RViz's LaserScan display draws it (src/rviz/default_plugin/laser_scan_display.cpp):
// projected into a PointCloud2 as laser_geometry's LaserProjection does (ros-perception/
// laser_geometry, src/laser_geometry.cpp projectLaser_), each beam placed in the fixed frame at its
// own time (transformLaserScanToPointCloud, which the display calls), then drawn by the point-cloud
// rules.
#pragma once

#include <Eigen/Geometry>

#include "display/point_cloud_message.h"

namespace urdfsnap::display {

// The scan's points in its own frame: range r of beam i at angle angle_min + i * angle_increment
// becomes (r cos a, r sin a, 0), kept when range_min <= r < range_max (so NaN and infinite ranges
// drop out); float32 fields x, y, z and, when the scan has intensities, "intensity" (a beam past
// the end of a short intensities list reads 0).
PointCloud2 ProjectLaserScan(const LaserScan& scan);

// The same points in the fixed frame, as transformLaserScanToPointCloud_ places them: beam i of n,
// measured at stamp + i * time_increment, moved by the transform interpolated from `X_start` (the
// scan's frame at its stamp) to `X_end` (at LastBeamStamp) with ratio i / (n - 1), the translation
// linearly and the rotation by slerp. With time_increment 0 (or a still frame) every beam gets
// X_start. The cloud's frame_id is "" (the fixed frame).
PointCloud2 ProjectLaserScan(const LaserScan& scan, const Eigen::Isometry3d& X_start, const Eigen::Isometry3d& X_end);

// When the scan's last beam was measured: stamp + (n - 1) * time_increment (the stamp for a stamp
// of 0, RViz's "latest", or fewer than two beams).
std::int64_t LastBeamStamp(const LaserScan& scan);

}  // namespace urdfsnap::display
