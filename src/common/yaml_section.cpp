// YamlSection over yaml-cpp. yaml-cpp's const operator[] gives an invalid node for a missing key,
// which throws on anything but IsDefined(); every function checks that first.
#include "common/internal/yaml_section.h"

#include <algorithm>

#include "common/error.h"
#include "common/number_text.h"

namespace urdfsnap {

YamlSection::YamlSection(std::string path, const YAML::Node& map, std::string name, Values values)
    : path_(std::move(path)), map_(map), name_(std::move(name)), values_(values) {
  if (!map_.IsMap()) {
    throw Error(SourceLocation{path_, LineOf(map_)}, name_ + ": expected a map, got " + DescribeYaml(map_));
  }
}

int YamlSection::KeyLine(const char* key) const {
  for (const auto& entry : map_) {
    if (entry.first.IsScalar() && entry.first.Scalar() == key) return LineOf(entry.first);
  }
  return LineOf(map_);
}

YAML::Node YamlSection::Entry(const char* key) const {
  const YAML::Node& map = map_;  // the const operator[]: the non-const one would add the key
  return map[key];
}

YAML::Node YamlSection::Value(const char* key) const {
  const YAML::Node entry = Entry(key);
  const bool nested = values_ == Values::kRvizProperties && entry.IsDefined() && entry.IsMap();
  return nested ? entry["Value"] : entry;
}

std::optional<YamlSection> YamlSection::Child(const char* key, const std::string& name) const {
  const YAML::Node entry = Entry(key);
  if (!entry.IsDefined()) return std::nullopt;
  return YamlSection(path_, entry, name, values_);
}

void YamlSection::ReadNumber(const char* key, double& out, double min, double max) const {
  const YAML::Node node = Value(key);
  if (!node.IsDefined()) return;
  double value = 0;
  if (!node.IsScalar() || !ParseNumber(node.Scalar(), value)) Fail(key, "a number");
  out = std::clamp(value, min, max);
}

void YamlSection::ReadInt(const char* key, int& out, int min) const {
  const YAML::Node node = Value(key);
  if (!node.IsDefined()) return;
  int value = 0;
  if (!node.IsScalar() || !ParseInteger(node.Scalar(), value)) Fail(key, "an integer");
  out = std::max(value, min);
}

void YamlSection::ReadBool(const char* key, bool& out) const {
  const YAML::Node node = Value(key);
  if (!node.IsDefined()) return;
  if (!node.IsScalar() || !YAML::convert<bool>::decode(node, out)) Fail(key, "true or false");
}

void YamlSection::ReadString(const char* key, std::string& out) const {
  const YAML::Node node = Value(key);
  if (!node.IsDefined()) return;
  if (!node.IsScalar()) Fail(key, "text");
  out = node.Scalar();
}

void YamlSection::Warn(const char* key, const std::string& what, Warnings& warnings) const {
  warnings.Add(SourceLocation{path_, KeyLine(key)}.ToString() + ": " + name_ + ": '" + key + "' " + what);
}

void YamlSection::Fail(const char* key, const std::string& expected) const {
  const YAML::Node value = Value(key);
  const YAML::Node shown = value.IsDefined() ? value : Entry(key);
  const int line = shown.IsDefined() && shown.IsScalar() ? LineOf(shown) : KeyLine(key);
  throw Error(SourceLocation{path_, line}, name_ + ": '" + key + "': expected " + expected + ", got " + DescribeYaml(shown));
}

}  // namespace urdfsnap
