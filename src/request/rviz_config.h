// Reads an RViz 1.14 `.rviz` file (YAML) into the scene options and orbit view urdfsnap honours,
// so that a user's saved RViz configuration renders the way RViz shows it.
#pragma once

#include <string>
#include <vector>

#include "common/warnings.h"
#include "display/display_settings.h"
#include "scene/orbit_view.h"
#include "scene/scene_options.h"

namespace urdfsnap::request {

// The parts of an .rviz file urdfsnap honours, applied on top of the given defaults.
struct RvizConfig {
  scene::SceneOptions scene;
  scene::OrbitView view;
  std::string target_frame;   // the orbit view's Target Frame; "" for <Fixed Frame>
  // the enabled Marker, MarkerArray, Path, PoseArray, Axes, PointCloud2 and LaserScan displays
  // (rviz_displays.cpp)
  std::vector<display::DisplaySettings> displays;
};

// Reads the file at `path` and applies to `defaults`:
//  - Global Options: Background Color, Fixed Frame;
//  - the Grid display (Cell Size, Plane Cell Count, Color, Alpha, Plane, Offset, enabled); a file
//    without an enabled Grid display turns the grid off;
//  - the RobotModel display (Alpha, Visual Enabled, Collision Enabled; disabled hides the robot);
//  - the TF display (enabled, Show Names, Show Axes, Show Arrows, Marker Scale);
//  - every enabled Marker, MarkerArray, Path, PoseArray, Axes, PointCloud2 and LaserScan display
//    (rviz_displays.cpp);
//  - Views/Current when it is an rviz/Orbit view (Distance, Yaw and Pitch in radians, Focal Point
//    in metres, Field of View in radians, Near Clip Distance in metres, Target Frame).
// Keys that are missing keep the defaults. Numbers are limited to the ranges RViz's properties
// allow. Displays in rviz/Group displays count as well. Adds one warning per display class that
// urdfsnap does not draw, and one for a current view that is not rviz/Orbit (the default view
// stays) or for properties it cannot honour (another reference frame, a 3D grid, ...).
// Throws urdfsnap::Error "FILE:LINE: ..." for an unreadable file, bad YAML or a bad value.
RvizConfig ReadRvizConfig(const std::string& path, const RvizConfig& defaults, Warnings& warnings);

// ReadRvizConfig for the text of a file already read; `path` names it in messages.
RvizConfig ParseRvizConfig(const std::string& text, const std::string& path,
                           const RvizConfig& defaults, Warnings& warnings);

}  // namespace urdfsnap::request
