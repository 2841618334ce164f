// The typed settings of RViz's PointCloud2 and LaserScan displays, which share one renderer
// (src/rviz/default_plugin/point_cloud_common.cpp) and its colour transformers
// (point_cloud_transformers.cpp); defaults are RViz 1.14's.
#pragma once

#include <string>

#include <Eigen/Core>

#include "scene/scene.h"

namespace urdfsnap::display {

struct PointCloudSettings {
  // point_cloud_transformers.cpp's colour transformers; kAuto picks as RViz does for a display
  // without one set (and for one the cloud cannot use): RGB8 when the cloud has an rgb or rgba
  // field, else Intensity
  enum class Colour { kAuto, kRgb8, kMono8, kRgbF32, kIntensity, kAxisColor, kFlatColor };

  scene::PointSet::Style style = scene::PointSet::Style::kFlatSquares;   // Style
  float size_m = 0.01f;          // Size (m): every style but Points
  float size_px = 3;             // Size (Pixels): Points
  float alpha = 1;               // Alpha, times each point's own (rgba)
  double decay_time = 0;         // Decay Time, seconds; 0: the latest message only
  Colour colour = Colour::kAuto; // Color Transformer
  // Intensity
  std::string channel = "intensity";   // Channel Name ("intensity" falls back to "intensities")
  bool use_rainbow = true;
  bool invert_rainbow = false;
  Eigen::Vector3f min_colour{0, 0, 0};
  Eigen::Vector3f max_colour{1, 1, 1};
  bool auto_intensity_bounds = true;   // Autocompute Intensity Bounds
  float min_intensity = 0;
  float max_intensity = 4096;
  // AxisColor
  int axis = 2;                        // Axis: 0 X, 1 Y, 2 Z
  bool auto_axis_bounds = true;        // Autocompute Value Bounds
  float min_value = -10;
  float max_value = 10;
  bool axis_in_fixed_frame = true;     // Use Fixed Frame
  // FlatColor
  Eigen::Vector3f flat_colour{1, 1, 1};   // Color

  bool operator==(const PointCloudSettings&) const = default;
};

}  // namespace urdfsnap::display
