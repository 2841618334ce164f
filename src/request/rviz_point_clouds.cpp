// Each point-cloud property read the way RViz's property classes load it, limited as RViz limits
// it (Size (m) >= 0.0001, Size (Pixels) >= 1, Alpha in [0, 1]).
#include "request/internal/rviz_point_clouds.h"

#include <array>
#include <string>
#include <utility>

#include "request/internal/rviz_properties.h"

namespace urdfsnap::request {
namespace {

using Style = scene::PointSet::Style;
using Colour = display::PointCloudSettings::Colour;

// Reads the enum property `key` among `options` (RViz's option names), failing with their list.
template <typename T, std::size_t N>
void ReadChoice(const YamlSection& section, const char* key, const std::array<std::pair<const char*, T>, N>& options,
                T& out) {
  if (!section.Value(key).IsDefined()) return;
  std::string text;
  section.ReadString(key, text);
  std::string names;
  for (const auto& [name, value] : options) {
    if (text == name) {
      out = value;
      return;
    }
    names += std::string(names.empty() ? "" : ", ") + (*name ? name : "\"\"");
  }
  section.Fail(key, "one of " + names);
}

void ReadFloat(const YamlSection& section, const char* key, float& out, double min = -1e30, double max = 1e30) {
  double value = out;
  section.ReadNumber(key, value, min, max);
  out = static_cast<float>(value);
}

}  // namespace

display::PointCloudSettings ReadPointCloudSettings(const YamlSection& section, Warnings& warnings) {
  display::PointCloudSettings s;
  ReadChoice<Style, 5>(section, "Style",
                       {{{"Points", Style::kPoints}, {"Squares", Style::kSquares}, {"Flat Squares", Style::kFlatSquares},
                         {"Spheres", Style::kSpheres}, {"Boxes", Style::kBoxes}}},
                       s.style);
  ReadFloat(section, "Size (m)", s.size_m, 0.0001);
  ReadFloat(section, "Size (Pixels)", s.size_px, 1);
  ReadFloat(section, "Alpha", s.alpha, 0, 1);
  section.ReadNumber("Decay Time", s.decay_time, 0);
  ReadChoice<Colour, 7>(section, "Color Transformer",
                        {{{"", Colour::kAuto}, {"RGB8", Colour::kRgb8}, {"MONO8", Colour::kMono8},
                          {"RGBF32", Colour::kRgbF32}, {"Intensity", Colour::kIntensity},
                          {"AxisColor", Colour::kAxisColor}, {"FlatColor", Colour::kFlatColor}}},
                        s.colour);
  std::string position = "XYZ";
  section.ReadString("Position Transformer", position);
  if (!position.empty() && position != "XYZ") {
    section.Warn("Position Transformer", "is '" + position + "'; urdfsnap places points by their x, y and z", warnings);
  }
  // Intensity
  section.ReadString("Channel Name", s.channel);
  section.ReadBool("Use rainbow", s.use_rainbow);
  section.ReadBool("Invert Rainbow", s.invert_rainbow);
  ReadColour(section, "Min Color", s.min_colour);
  ReadColour(section, "Max Color", s.max_colour);
  section.ReadBool("Autocompute Intensity Bounds", s.auto_intensity_bounds);
  ReadFloat(section, "Min Intensity", s.min_intensity);
  ReadFloat(section, "Max Intensity", s.max_intensity);
  // AxisColor: Min Value and Max Value are saved under Autocompute Value Bounds
  ReadChoice<int, 3>(section, "Axis", {{{"X", 0}, {"Y", 1}, {"Z", 2}}}, s.axis);
  section.ReadBool("Autocompute Value Bounds", s.auto_axis_bounds);
  if (const YAML::Node node = section.Entry("Autocompute Value Bounds"); node.IsDefined() && node.IsMap()) {
    const auto bounds = section.Child("Autocompute Value Bounds", section.name() + ": 'Autocompute Value Bounds'");
    ReadFloat(*bounds, "Min Value", s.min_value);
    ReadFloat(*bounds, "Max Value", s.max_value);
  }
  section.ReadBool("Use Fixed Frame", s.axis_in_fixed_frame);
  // FlatColor
  ReadColour(section, "Color", s.flat_colour);
  return s;
}

}  // namespace urdfsnap::request
