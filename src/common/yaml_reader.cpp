// YamlReader over yaml-cpp. yaml-cpp throws for a key looked up in a scalar or a list (found by
// fuzzing), so Field checks for a map first; its marks count lines from 0 within the document.
#include "common/internal/yaml_reader.h"

#include "common/error.h"
#include "common/number_text.h"

namespace urdfsnap {

int LineOf(const YAML::Node& node) { return node.IsDefined() ? node.Mark().line + 1 : 0; }

std::string DescribeYaml(const YAML::Node& node) {
  if (!node.IsDefined()) return "nothing";
  if (node.IsScalar()) return "'" + node.Scalar() + "'";
  if (node.IsMap()) return "a map";
  if (node.IsSequence()) return "a list";
  return "nothing";
}

YamlReader::YamlReader(std::string path, int first_line) : path_(std::move(path)), first_line_(first_line) {}

YAML::Node YamlReader::Load(const std::string& text) const {
  try {
    return YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw Error(SourceLocation{path_, e.mark.is_null() ? first_line_ : first_line_ + e.mark.line}, "bad YAML: " + e.msg);
  }
}

int YamlReader::Line(const YAML::Node& node) const {
  return node.IsDefined() && !node.Mark().is_null() ? first_line_ + node.Mark().line : 0;
}

SourceLocation YamlReader::Where(const YAML::Node& node) const { return {path_, Line(node)}; }

void YamlReader::Fail(const YAML::Node& node, const std::string& what) const { throw Error(Where(node), what); }

YAML::Node YamlReader::Field(const YAML::Node& map, const char* key, const std::string& of) const {
  if (!map.IsMap()) Fail(map, of + " is not a map");
  const YAML::Node value = map[key];
  if (!value) Fail(map, of + " has no '" + key + "'");
  return value;
}

double YamlReader::Number(const YAML::Node& node, const std::string& what) const {
  double value = 0;
  if (!node.IsScalar() || !ParseNumber(node.Scalar(), value)) {
    Fail(node, what + ": expected a finite number, got " + (node.IsScalar() || node.IsNull() ? DescribeYaml(node) : "a list or map"));
  }
  return value;
}

std::vector<double> YamlReader::Numbers(const YAML::Node& list, const std::string& what) const {
  if (!list.IsSequence()) Fail(list, "'" + what + "' is not a list of numbers");
  std::vector<double> numbers;
  for (const YAML::Node& item : list) numbers.push_back(Number(item, what));
  return numbers;
}

std::vector<std::string> YamlReader::Names(const YAML::Node& list, const std::string& what) const {
  if (!list.IsSequence()) Fail(list, "'" + what + "' is not a list of names");
  std::vector<std::string> names;
  for (const YAML::Node& item : list) {
    if (!item.IsScalar()) Fail(item, "'" + what + "' holds something not a name");
    names.push_back(item.Scalar());
  }
  return names;
}

YAML::Node LoadYaml(const std::string& text, const std::string& path) { return YamlReader(path).Load(text); }

}  // namespace urdfsnap
