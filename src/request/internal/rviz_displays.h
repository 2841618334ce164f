// The message displays of a `.rviz` file (Marker, MarkerArray, Path, PoseArray, Axes, PointCloud2,
// LaserScan) read into display/display_settings.h's typed settings, RViz 1.14's property names and
// RViz 2's (rviz_default_plugins) alike.
#pragma once

#include "common/internal/yaml_section.h"
#include "common/warnings.h"
#include "display/display_settings.h"
#include "request/rviz_class_names.h"

namespace urdfsnap::request {

// Whether `kind` is a display that display/ draws from messages.
bool IsMessageDisplay(DisplayClass kind);

// The settings of the display `section` (of class `kind`, IsMessageDisplay) named `name`; missing
// properties keep RViz's defaults. Warns of properties urdfsnap does not honour; throws
// urdfsnap::Error at the line of a bad value.
display::DisplaySettings ReadMessageDisplay(DisplayClass kind, const YamlSection& section,
                                            const std::string& name, Warnings& warnings);

}  // namespace urdfsnap::request
