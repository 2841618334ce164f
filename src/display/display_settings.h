// The typed settings of each RViz display urdfsnap draws, with RViz 1.14's defaults (the
// constructors of src/rviz/default_plugin/*_display.cpp). A .rviz config, --display and the C++
// API fill them; display/make_display.h turns them into a display. A new display type adds its
// settings struct to DisplayKind and its class to MakeDisplay.
#pragma once

#include <map>
#include <string>
#include <variant>

#include <Eigen/Core>

#include "display/point_cloud_settings.h"

namespace urdfsnap::display {

// marker_display.cpp / marker_array_display.cpp: Marker Topic (/visualization_marker or
// /visualization_marker_array) and the Namespaces list, each namespace shown unless set false.
struct MarkerSettings {
  bool array = false;   // MarkerArray messages rather than single Markers
  std::map<std::string, bool> namespaces;

  bool operator==(const MarkerSettings&) const = default;
};

// path_display.cpp: Line Style Lines (1-pixel lines) or Billboards (ribbons Line Width wide),
// Color 25;255;0, Alpha 1, Line Width 0.03, Buffer Length 1, Offset 0;0;0. Pose Style stays None.
struct PathSettings {
  enum class LineStyle { kLines, kBillboards };
  LineStyle line_style = LineStyle::kLines;
  Eigen::Vector3f colour{25 / 255.f, 1, 0};
  float alpha = 1;
  double line_width = 0.03;
  int buffer_length = 1;
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();

  bool operator==(const PathSettings&) const = default;
};

// pose_array_display.cpp: Shape Arrow (Flat) (lines Arrow Length long), Arrow (3D) (head and
// shaft radius and length) or Axes (length, radius); Color 255;25;0, Alpha 1.
struct PoseArraySettings {
  enum class Shape { kArrowFlat, kArrow3d, kAxes };
  Shape shape = Shape::kArrowFlat;
  Eigen::Vector3f colour{1, 25 / 255.f, 0};
  float alpha = 1;
  double arrow_length = 0.3;
  double head_radius = 0.03;
  double head_length = 0.07;
  double shaft_radius = 0.01;
  double shaft_length = 0.23;
  double axes_length = 0.3;
  double axes_radius = 0.01;

  bool operator==(const PoseArraySettings&) const = default;
};

// axes_display.cpp: axes of Length 1 and Radius 0.1 at Reference Frame ("" = the fixed frame).
struct AxesSettings {
  std::string reference_frame;
  double length = 1;
  double radius = 0.1;

  bool operator==(const AxesSettings&) const = default;
};

// point_cloud2_display.cpp and laser_scan_display.cpp: the same point-cloud settings
// (point_cloud_common.cpp), for PointCloud2 messages or LaserScans.
struct CloudSettings {
  bool laser_scan = false;
  PointCloudSettings points;

  bool operator==(const CloudSettings&) const = default;
};

using DisplayKind = std::variant<MarkerSettings, PathSettings, PoseArraySettings, AxesSettings, CloudSettings>;

// One display as a config lists it.
struct DisplaySettings {
  std::string name;    // as the config names it, for messages
  std::string topic;   // "" for displays without one (Axes)
  DisplayKind kind;

  bool operator==(const DisplaySettings&) const = default;
};

}  // namespace urdfsnap::display
