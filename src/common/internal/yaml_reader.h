// Located YAML: a document loaded with its parse error at a line, and a YamlReader that reads
// nodes of it into typed values, every bad value an urdfsnap::Error "PATH:LINE: what" at the line
// of the node that is wrong. Every YAML input goes through it: .rviz files and joint files (with
// YamlSection, yaml_section.h, for maps read key by key), suite files, trajectory and other ROS
// message files (several documents in one file), camera calibrations, rosbag2 metadata. Private
// to the build (not installed): it names yaml-cpp's types.
#pragma once

#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "common/error.h"

namespace urdfsnap {

// A node's 1-based line; 0 (the whole file) when the node has none.
int LineOf(const YAML::Node& node);

// What a node is, for messages: "'text'", "a map", "a list" or "nothing".
std::string DescribeYaml(const YAML::Node& node);

// Reads the nodes of one YAML document of the file `path` whose text starts at line `first_line`
// of the file (a file of several "---" documents), lines counted in the whole file.
class YamlReader {
 public:
  explicit YamlReader(std::string path, int first_line = 1);

  const std::string& path() const { return path_; }

  // Parses `text` (the document); throws "PATH:LINE: bad YAML: ..." at the parser's line.
  YAML::Node Load(const std::string& text) const;

  // `node`'s line in the file; 0 (the whole file) when the node has none.
  int Line(const YAML::Node& node) const;
  // The file and that line.
  SourceLocation Where(const YAML::Node& node) const;

  // Throws urdfsnap::Error "PATH:LINE: what" at `node`'s line.
  [[noreturn]] void Fail(const YAML::Node& node, const std::string& what) const;

  // `map[key]`, which must be there: else "OF is not a map" or "OF has no 'KEY'" at `map`.
  YAML::Node Field(const YAML::Node& map, const char* key, const std::string& of) const;

  // A finite number (common/number_text.h's grammar); else "WHAT: expected a finite number, got ...".
  double Number(const YAML::Node& node, const std::string& what) const;
  // A list of them; else "'WHAT' is not a list of numbers".
  std::vector<double> Numbers(const YAML::Node& list, const std::string& what) const;
  // A list of scalars; else "'WHAT' is not a list of names" or "'WHAT' holds something not a name".
  std::vector<std::string> Names(const YAML::Node& list, const std::string& what) const;

 private:
  std::string path_;
  int first_line_;
};

// Parses the whole file `path`'s `text`; throws "PATH:LINE: bad YAML: ..." at the parser's line.
YAML::Node LoadYaml(const std::string& text, const std::string& path);

}  // namespace urdfsnap
