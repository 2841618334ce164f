// The one place a display's settings become a display: each settings type of DisplayKind maps to
// its class here.
#pragma once

#include <memory>

#include "display/display.h"
#include "display/display_settings.h"
#include "display/marker_shapes.h"

namespace urdfsnap::display {

// A display of RViz class `class_name` ("MarkerArray", "rviz/Path", "rviz_default_plugins/PoseArray",
// ...: Marker, MarkerArray, Path, PoseArray, Axes, PointCloud2, LaserScan) on `topic` with RViz's
// defaults (--display).
// Throws urdfsnap::Error naming the classes known for another name.
DisplaySettings DefaultDisplay(const std::string& class_name, const std::string& topic);

// Every message type a display draws, as "pkg/msg/Type" joined by ", " (the --message types).
std::string DrawnMessageTypes();

// The display RViz draws messages of `type` ("visualization_msgs/msg/MarkerArray", ...) with, with
// its defaults, on `topic` (message files). Throws urdfsnap::Error for a type no display draws.
DisplaySettings DefaultDisplayForType(const std::string& type, const std::string& topic);

// `fixed_frame`: the frame the scene is drawn in (the Axes display's default reference frame).
std::unique_ptr<Display> MakeDisplay(const DisplaySettings& settings, const std::string& fixed_frame,
                                     const MarkerResources& resources);

}  // namespace urdfsnap::display
