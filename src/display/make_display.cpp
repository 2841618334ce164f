// Settings to display classes.
#include "display/make_display.h"

#include <array>
#include <utility>

#include "bag/message_schema.h"
#include "common/error.h"
#include "display/axes_display.h"
#include "display/marker_display.h"
#include "display/path_display.h"
#include "display/point_cloud_display.h"
#include "display/pose_array_display.h"

namespace urdfsnap::display {
namespace {
template <class... Ts>
struct Overloaded : Ts... {
  using Ts::operator()...;
};
// (clang 14, the sanitizer build's compiler, deduces an aggregate's arguments only with a guide)
template <class... Ts>
Overloaded(Ts...) -> Overloaded<Ts...>;
// RViz's display class names (without the rviz/ or rviz_default_plugins/ prefix), the message
// type each draws and its default settings.
struct Known {
  const char* class_name;
  const char* type;
  DisplayKind defaults;
};
const std::array<Known, 7>& KnownDisplays() {
  static const std::array<Known, 7> known = {{
      {"Marker", "visualization_msgs/Marker", MarkerSettings{false, {}}},
      {"MarkerArray", "visualization_msgs/MarkerArray", MarkerSettings{true, {}}},
      {"Path", "nav_msgs/Path", PathSettings{}},
      {"PoseArray", "geometry_msgs/PoseArray", PoseArraySettings{}},
      {"Axes", "", AxesSettings{}},
      {"PointCloud2", "sensor_msgs/PointCloud2", CloudSettings{false, {}}},
      {"LaserScan", "sensor_msgs/LaserScan", CloudSettings{true, {}}},
  }};
  return known;
}

}  // namespace

DisplaySettings DefaultDisplay(const std::string& class_name, const std::string& topic) {
  std::string name = class_name;
  for (const char* prefix : {"rviz/", "rviz_default_plugins/"}) {
    if (name.starts_with(prefix)) name.erase(0, std::string(prefix).size());
  }
  std::string names;
  for (const Known& known : KnownDisplays()) {
    if (name == known.class_name) return {name, topic, known.defaults};
    names += std::string(names.empty() ? "" : ", ") + known.class_name;
  }
  throw Error("unknown display class '" + class_name + "'; urdfsnap draws " + names);
}

std::string DrawnMessageTypes() {
  std::string types;
  for (const Known& known : KnownDisplays()) {
    const std::string type = known.type;
    if (type.empty()) continue;
    types += (types.empty() ? "" : ", ") + type.substr(0, type.find('/')) + "/msg" + type.substr(type.find('/'));
  }
  return types;
}

DisplaySettings DefaultDisplayForType(const std::string& type, const std::string& topic) {
  const std::string short_type = bag::ShortTypeName(type);
  for (const Known& known : KnownDisplays()) {
    if (short_type == known.type) return {known.class_name, topic, known.defaults};
  }
  throw Error("no display draws messages of type '" + type + "'; urdfsnap draws " + DrawnMessageTypes());
}

std::unique_ptr<Display> MakeDisplay(const DisplaySettings& settings, const std::string& fixed_frame,
                                     const MarkerResources& resources) {
  return std::visit(
      Overloaded{
          [&](const MarkerSettings& s) -> std::unique_ptr<Display> {
            return std::make_unique<MarkerDisplay>(settings.topic, s, resources);
          },
          [&](const PathSettings& s) -> std::unique_ptr<Display> {
            return std::make_unique<PathDisplay>(settings.topic, s);
          },
          [&](const PoseArraySettings& s) -> std::unique_ptr<Display> {
            return std::make_unique<PoseArrayDisplay>(settings.topic, s);
          },
          [&](const AxesSettings& s) -> std::unique_ptr<Display> {
            return std::make_unique<AxesDisplay>(s, fixed_frame);
          },
          [&](const CloudSettings& s) -> std::unique_ptr<Display> {
            return std::make_unique<PointCloudDisplay>(settings.topic, s);
          }},
      settings.kind);
}

}  // namespace urdfsnap::display
