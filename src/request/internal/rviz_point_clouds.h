// The properties of RViz's PointCloud2 and LaserScan displays as a .rviz file saves them (RViz 1
// rviz/PointCloud2 and rviz/LaserScan, RViz 2 rviz_default_plugins/PointCloud2 and LaserScan: the
// same names, from point_cloud_common.cpp and point_cloud_transformers.cpp), read into
// display::PointCloudSettings with RViz's defaults for what is not written.
#pragma once

#include "common/internal/yaml_section.h"
#include "common/warnings.h"
#include "display/point_cloud_settings.h"

namespace urdfsnap::request {

// Style, Size (m), Size (Pixels), Alpha, Decay Time, Color Transformer and each transformer's
// properties (Channel Name, Use rainbow, Invert Rainbow, Min/Max Color, Autocompute Intensity
// Bounds, Min/Max Intensity; Axis, Autocompute Value Bounds with Min/Max Value, Use Fixed Frame;
// Color). Throws urdfsnap::Error at the line of a value that cannot be read; a Position
// Transformer other than XYZ is a warning.
display::PointCloudSettings ReadPointCloudSettings(const YamlSection& section, Warnings& warnings);

}  // namespace urdfsnap::request
