// A map of a located YAML document (yaml_reader.h) read key by key into typed values, each bad
// value an urdfsnap::Error at the line of the value that is wrong ("view.rviz:12: Grid display
// 'Grid': 'Alpha': expected a number, got 'x'"): .rviz files and joint files. Private to the build
// (not installed): it names yaml-cpp's types.
#pragma once

#include <limits>
#include <optional>
#include <string>

#include <yaml-cpp/yaml.h>

#include "common/internal/yaml_reader.h"
#include "common/warnings.h"

namespace urdfsnap {

// One map of a file and the name messages give it. The Read functions leave `out` alone when
// `key` is missing and throw urdfsnap::Error at the value's line when it cannot be read.
class YamlSection {
 public:
  // How a key's value is stored.
  enum class Values {
    kPlain,           // key: value
    kRvizProperties,  // also key: {Value: value, sub-properties...}, as RViz saves a property
                      // with sub-properties (Property::load, src/rviz/properties/property.cpp)
  };

  // Throws urdfsnap::Error at `map`'s line unless it is a map.
  YamlSection(std::string path, const YAML::Node& map, std::string name, Values values = Values::kPlain);

  const std::string& path() const { return path_; }
  const std::string& name() const { return name_; }

  // The line of `key` itself (a map's own mark is its first entry), else the section's line.
  int KeyLine(const char* key) const;

  // The entry `key` as written (undefined when missing; never adds the key).
  YAML::Node Entry(const char* key) const;

  // The value of `key` (with kRvizProperties, a map's "Value" entry).
  YAML::Node Value(const char* key) const;

  // A section for the map at `key` (same value rule), or nothing when the key is missing.
  std::optional<YamlSection> Child(const char* key, const std::string& name) const;

  // A finite number (common/number_text.h's grammar), clamped to [min, max].
  void ReadNumber(const char* key, double& out, double min = -std::numeric_limits<double>::infinity(),
                  double max = std::numeric_limits<double>::infinity()) const;
  // A decimal integer, raised to `min` when below it.
  void ReadInt(const char* key, int& out, int min) const;
  void ReadBool(const char* key, bool& out) const;
  void ReadString(const char* key, std::string& out) const;

  // Warns (once per message) that `key` is set to something that is not honoured: "what".
  void Warn(const char* key, const std::string& what, Warnings& warnings) const;

  // Throws at the offending scalar's line, else at the key's, else at the section's:
  // "NAME: 'KEY': expected EXPECTED, got ...".
  [[noreturn]] void Fail(const char* key, const std::string& expected) const;

 private:
  std::string path_;
  YAML::Node map_;
  std::string name_;
  Values values_;
};

}  // namespace urdfsnap
