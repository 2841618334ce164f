// The message display options of the drawing commands: --display CLASS:TOPIC adds an RViz display
// with RViz's defaults (as a .rviz file's displays are added), --message FILE:TYPE draws a message
// file (`ros2 topic echo` YAML) with the display RViz draws that type with.
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "common/warnings.h"
#include "display/display_set.h"

namespace urdfsnap::cli {

struct DisplayOptions {
  std::vector<std::string> displays;   // CLASS:TOPIC
  std::vector<std::string> messages;   // FILE:TYPE

  void AddOptions(CLI::App& cmd);
  bool empty() const { return displays.empty() && messages.empty(); }

  // The displays of `from_config` (a .rviz file's), then --display's, then one per --message, and
  // the message files' messages given to them. Throws urdfsnap::Error for a bad option value or an
  // unreadable message file.
  display::DisplaySet MakeDisplays(const std::vector<display::DisplaySettings>& from_config,
                                   const std::string& fixed_frame, const display::MarkerResources& resources,
                                   Warnings& warnings) const;
};

}  // namespace urdfsnap::cli
