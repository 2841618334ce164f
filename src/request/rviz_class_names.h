// The display and view classes urdfsnap follows in a `.rviz` file, by the names RViz 1 saves
// (rviz/Grid, rviz/Orbit, ...) and the names RViz 2 saves (rviz_default_plugins/Grid,
// rviz_common/Group, rviz_default_plugins/Orbit, ...). Both RViz versions give these classes the
// same property names, so one reader serves both once the class is known.
#pragma once

#include <string_view>

namespace urdfsnap::request {

// What a display of a `.rviz` file is to urdfsnap.
enum class DisplayClass {
  kGrid,        // rviz/Grid, rviz_default_plugins/Grid
  kRobotModel,  // rviz/RobotModel, rviz_default_plugins/RobotModel
  kTf,          // rviz/TF, rviz_default_plugins/TF
  kGroup,       // rviz/Group, rviz_common/Group: holds further displays
  kMarker,      // rviz/Marker, rviz_default_plugins/Marker
  kMarkerArray, // rviz/MarkerArray, rviz_default_plugins/MarkerArray
  kPath,        // rviz/Path, rviz_default_plugins/Path
  kPoseArray,   // rviz/PoseArray, rviz_default_plugins/PoseArray
  kAxes,        // rviz/Axes, rviz_default_plugins/Axes
  kPointCloud2, // rviz/PointCloud2, rviz_default_plugins/PointCloud2
  kLaserScan,   // rviz/LaserScan, rviz_default_plugins/LaserScan
  kOther,       // anything else: a display urdfsnap does not draw
};

// The kind of the display class `class_id` as written in the file's "Class" key.
DisplayClass ClassifyDisplay(std::string_view class_id);

// Whether the view class `class_id` is RViz's orbit view (rviz/Orbit, rviz_default_plugins/Orbit).
bool IsOrbitView(std::string_view class_id);

}  // namespace urdfsnap::request
