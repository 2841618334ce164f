// The class names of RViz 1's plugin description (src/rviz/default_plugin/plugin_description.xml
// in ros-visualization/rviz) and RViz 2's (rviz_default_plugins/plugins_description.xml and
// rviz_common's built-in Group display in ros2/rviz) for the displays and views urdfsnap follows.
#include "request/rviz_class_names.h"

#include <array>
#include <utility>

namespace urdfsnap::request {
namespace {

constexpr std::array<std::pair<std::string_view, DisplayClass>, 22> kDisplayClasses = {{
    {"rviz/Grid", DisplayClass::kGrid},
    {"rviz_default_plugins/Grid", DisplayClass::kGrid},
    {"rviz/RobotModel", DisplayClass::kRobotModel},
    {"rviz_default_plugins/RobotModel", DisplayClass::kRobotModel},
    {"rviz/TF", DisplayClass::kTf},
    {"rviz_default_plugins/TF", DisplayClass::kTf},
    {"rviz/Group", DisplayClass::kGroup},
    {"rviz_common/Group", DisplayClass::kGroup},
    {"rviz/Marker", DisplayClass::kMarker},
    {"rviz_default_plugins/Marker", DisplayClass::kMarker},
    {"rviz/MarkerArray", DisplayClass::kMarkerArray},
    {"rviz_default_plugins/MarkerArray", DisplayClass::kMarkerArray},
    {"rviz/Path", DisplayClass::kPath},
    {"rviz_default_plugins/Path", DisplayClass::kPath},
    {"rviz/PoseArray", DisplayClass::kPoseArray},
    {"rviz_default_plugins/PoseArray", DisplayClass::kPoseArray},
    {"rviz/Axes", DisplayClass::kAxes},
    {"rviz_default_plugins/Axes", DisplayClass::kAxes},
    {"rviz/PointCloud2", DisplayClass::kPointCloud2},
    {"rviz_default_plugins/PointCloud2", DisplayClass::kPointCloud2},
    {"rviz/LaserScan", DisplayClass::kLaserScan},
    {"rviz_default_plugins/LaserScan", DisplayClass::kLaserScan},
}};

}  // namespace

DisplayClass ClassifyDisplay(std::string_view class_id) {
  for (const auto& [name, kind] : kDisplayClasses) {
    if (name == class_id) return kind;
  }
  return DisplayClass::kOther;
}

bool IsOrbitView(std::string_view class_id) {
  return class_id == "rviz/Orbit" || class_id == "rviz_default_plugins/Orbit";
}

}  // namespace urdfsnap::request
