// The displays of one render: made from their settings, fed the messages of their topics (from a
// bag, or a message file), drawn together into a scene. What a command uses:
//
//   display::DisplaySet displays(config.displays, fixed_frame, resources);
//   display::BagDisplayFeed feed(bag, displays);   // display/bag_display_feed.h
//   feed.AdvanceTo(until_ns, warnings);
//   scene::Scene scene = robot.Pose(positions);
//   displays.Draw(until_ns, lookup, scene, warnings);
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "display/display.h"
#include "display/display_settings.h"
#include "display/marker_shapes.h"

namespace urdfsnap::display {

class DisplaySet {
 public:
  DisplaySet(const std::vector<DisplaySettings>& settings, const std::string& fixed_frame,
             const MarkerResources& resources);
  DisplaySet() = default;

  // Adds a display made elsewhere (one a command reads, such as a camera image), named `name` in
  // warnings; it stays where it is while the set lives.
  Display& Add(std::string name, std::unique_ptr<Display> display);

  // Whether any display subscribes to `topic`.
  bool Subscribes(const std::string& topic) const;

  // Gives a decoded message of `type` on `topic`, received at `time_ns`, to every display of that
  // topic that reads the type; one that does not is warned of (as RViz's display status says),
  // once per topic. `where` names the message in warnings and errors. Throws urdfsnap::Error
  // "WHERE: ..." when the message lacks a field a display reads.
  void Receive(const std::string& topic, const std::string& type, const bag::MessageValue& message,
               std::int64_t time_ns, const std::string& where, Warnings& warnings);

  // Every display's scene items at `time_ns`, in the displays' order.
  void Draw(std::int64_t time_ns, const FrameLookup& lookup, scene::Scene& scene, Warnings& warnings) const;

  bool empty() const { return displays_.empty(); }

 private:
  std::vector<std::string> names_;
  std::vector<std::unique_ptr<Display>> displays_;
};

}  // namespace urdfsnap::display
