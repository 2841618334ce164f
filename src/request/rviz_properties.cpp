// The shared RViz property readers, moved here from rviz_config.cpp so that the display readers
// (request/rviz_displays.cpp) read colours, frames and vectors the same way.
#include "request/internal/rviz_properties.h"

#include <algorithm>
#include <string_view>

#include "common/number_text.h"

namespace urdfsnap::request {
namespace {

std::string_view Trimmed(std::string_view text) {
  const size_t begin = text.find_first_not_of(' ');
  if (begin == std::string_view::npos) return {};
  return text.substr(begin, text.find_last_not_of(' ') - begin + 1);
}

}  // namespace

// A section of the file: RViz saves a property with sub-properties as a map with its "Value".
YamlSection RvizSection(const std::string& path, const YAML::Node& map, const std::string& name) {
  return YamlSection(path, map, name, YamlSection::Values::kRvizProperties);
}

// A TF frame name; RViz drops a leading '/' (TfFrameProperty::setValue, tf_frame_property.cpp).
void ReadFrame(const YamlSection& section, const char* key, std::string& out) {
  section.ReadString(key, out);
  if (!out.empty() && out.front() == '/') out.erase(0, 1);
}

// ColorProperty's "R; G; B" with each integer limited to 0..255 (parseColor, parse_color.cpp).
void ReadColour(const YamlSection& section, const char* key, Eigen::Vector3f& out) {
  const YAML::Node node = section.Value(key);
  if (!node.IsDefined()) return;
  const char* expected = "a colour \"R; G; B\" (three integers)";
  if (!node.IsScalar()) section.Fail(key, expected);
  const std::string_view text = node.Scalar();
  Eigen::Vector3f colour;
  size_t begin = 0;
  for (int i = 0; i < 3; ++i) {
    const size_t end = i < 2 ? text.find(';', begin) : text.size();
    int value = 0;
    if (end == std::string_view::npos || !ParseInteger(Trimmed(text.substr(begin, end - begin)), value)) {
      section.Fail(key, expected);
    }
    colour[i] = static_cast<float>(std::clamp(value, 0, 255)) / 255.f;
    begin = end + 1;
  }
  out = colour;
}

// VectorProperty's map of X, Y and Z, all three or none (VectorProperty::load,
// vector_property.cpp).
void ReadVector(const YamlSection& section, const char* key, Eigen::Vector3d& out) {
  const YAML::Node node = section.Entry(key);
  if (!node.IsDefined()) return;
  const YamlSection vector = RvizSection(section.path(), node, section.name() + ": '" + key + "'");
  Eigen::Vector3d value;
  const char* const axes[] = {"X", "Y", "Z"};
  for (int i = 0; i < 3; ++i) {
    if (!vector.Entry(axes[i]).IsDefined()) section.Fail(key, "a map of X, Y and Z");
    vector.ReadNumber(axes[i], value[i]);
  }
  out = value;
}

}  // namespace urdfsnap::request
