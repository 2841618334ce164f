// --display and --message parsed into display settings, message files read into the displays.
#include "cli/display_options.h"

#include "common/error.h"
#include "display/make_display.h"
#include "display/message_file.h"

namespace urdfsnap::cli {
namespace {

// "A:B" split at its last ':' (a file name may hold one, a type or topic does not).
std::pair<std::string, std::string> SplitLast(const std::string& value, const std::string& option,
                                              const std::string& expected) {
  const size_t colon = value.rfind(':');
  if (colon == std::string::npos || colon == 0) throw Error(option + " '" + value + "': expected " + expected);
  return {value.substr(0, colon), value.substr(colon + 1)};
}

}  // namespace

void DisplayOptions::AddOptions(CLI::App& cmd) {
  cmd.add_option("--display", displays,
                 "add an RViz display with RViz's defaults: CLASS:TOPIC, CLASS one of Marker, "
                 "MarkerArray, Path, PoseArray, Axes, PointCloud2, LaserScan (Axes: no topic, e.g. Axes:); "
                 "repeatable")
      ->take_all();
  cmd.add_option("--message", messages,
                 "draw a message file: FILE:TYPE, FILE as `ros2 topic echo` prints a message (the "
                 "last of several), TYPE one of " + display::DrawnMessageTypes() +
                     ", drawn as RViz's display of that type with its defaults, in frames of the robot's "
                     "links; repeatable")
      ->take_all();
}

display::DisplaySet DisplayOptions::MakeDisplays(const std::vector<display::DisplaySettings>& from_config,
                                                 const std::string& fixed_frame,
                                                 const display::MarkerResources& resources,
                                                 Warnings& warnings) const {
  std::vector<display::DisplaySettings> settings = from_config;
  for (const std::string& value : displays) {
    const auto [class_name, topic] = SplitLast(value, "--display", "CLASS:TOPIC, e.g. MarkerArray:/markers");
    settings.push_back(display::DefaultDisplay(class_name, topic));
  }
  std::vector<display::MessageFile> files;
  for (size_t i = 0; i < messages.size(); ++i) {
    const auto [file, type] =
        SplitLast(messages[i], "--message", "FILE:TYPE, e.g. markers.yaml:visualization_msgs/msg/MarkerArray");
    // each file its own display on a topic of its own
    settings.push_back(display::DefaultDisplayForType(type, "--message " + std::to_string(i + 1)));
    files.push_back(display::ReadMessageFile(file, type));
  }
  display::DisplaySet set(settings, fixed_frame, resources);
  for (size_t i = 0; i < messages.size(); ++i) {
    const auto [file, type] = SplitLast(messages[i], "--message", "");
    set.Receive("--message " + std::to_string(i + 1), type, files[i].value, 0, file, warnings);
  }
  return set;
}

}  // namespace urdfsnap::cli
