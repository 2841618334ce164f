// A LaserScan as RViz's LaserScan display draws it (src/rviz/default_plugin/laser_scan_display.cpp):
// projected into a PointCloud2 as laser_geometry's LaserProjection does (ros-perception/
// laser_geometry, src/laser_geometry.cpp projectLaser_), then drawn by the point-cloud rules.
#pragma once

#include "display/point_cloud_message.h"

namespace urdfsnap::display {

// The scan's points in its own frame: range r of beam i at angle angle_min + i * angle_increment
// becomes (r cos a, r sin a, 0), kept when range_min <= r < range_max (so NaN and infinite ranges
// drop out); float32 fields x, y, z and, when the scan has intensities, "intensity" (a beam past
// the end of a short intensities list reads 0). RViz projects each beam at its own time through
// TF (time_increment); here the whole scan is placed at its stamp.
PointCloud2 ProjectLaserScan(const LaserScan& scan);

}  // namespace urdfsnap::display
