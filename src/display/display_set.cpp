// Display construction and message routing by topic.
#include "display/display_set.h"

#include <utility>

#include "bag/cdr_reader.h"
#include "common/error.h"
#include "display/make_display.h"

namespace urdfsnap::display {

DisplaySet::DisplaySet(const std::vector<DisplaySettings>& settings, const std::string& fixed_frame,
                       const MarkerResources& resources) {
  for (const DisplaySettings& s : settings) {
    names_.push_back(s.name);
    displays_.push_back(MakeDisplay(s, fixed_frame, resources));
  }
}

Display& DisplaySet::Add(std::string name, std::unique_ptr<Display> display) {
  names_.push_back(std::move(name));
  displays_.push_back(std::move(display));
  return *displays_.back();
}

bool DisplaySet::Subscribes(const std::string& topic) const {
  for (const auto& display : displays_) {
    if (!display->topic().empty() && display->topic() == topic) return true;
  }
  return false;
}

void DisplaySet::Receive(const std::string& topic, const std::string& type, const bag::MessageValue& message,
                         std::int64_t time_ns, const std::string& where, Warnings& warnings) {
  for (size_t i = 0; i < displays_.size(); ++i) {
    Display& display = *displays_[i];
    if (display.topic() != topic) continue;
    if (!display.Reads(type)) {
      warnings.Add("display '" + names_[i] + "': topic '" + topic + "' carries '" + type +
                   "' messages, which it does not draw");
      continue;
    }
    try {
      display.Receive(message, time_ns, where, warnings);
    } catch (const bag::CdrError& e) {
      throw Error(where + ": " + e.what());
    }
  }
}

void DisplaySet::Draw(std::int64_t time_ns, const FrameLookup& lookup, scene::Scene& scene,
                      Warnings& warnings) const {
  for (const auto& display : displays_) display->Draw(time_ns, lookup, scene, warnings);
}

}  // namespace urdfsnap::display
