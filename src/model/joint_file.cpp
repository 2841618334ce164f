// ReadJointFile: YAML (yaml-cpp) or JSON (nlohmann_json) joint files, both read into the same
// list of top-level entries (in file order) and then interpreted as a {name: value} map or a JointState.
#include <algorithm>

#include "common/error.h"
#include "common/internal/yaml_section.h"
#include "common/file_reading.h"
#include "common/json_text.h"
#include "model/joint_values.h"
#include "common/number_text.h"

namespace urdfsnap::model {

namespace {

// One scalar of a joint file: a number, or text that is not one.
struct Scalar {
  std::string text;
  bool is_number = false;
  double number = 0;
  int line = 0;
};

// One top-level key of a joint file with its scalar or list of scalars.
struct Entry {
  std::string key;
  int line = 0;
  bool is_list = false;
  std::vector<Scalar> items;  // one item unless is_list
};

std::string ReadText(const std::string& path) {
  try {
    return ReadFileBounded(path);
  } catch (const FileReadError& e) {
    throw Error(SourceLocation{path, 0}, std::string("cannot read the joint file: ") + e.what());
  }
}

Scalar ScalarFromText(const std::string& text, int line) {
  Scalar scalar{text, false, 0, line};
  scalar.is_number = ParseNumber(text, scalar.number);
  return scalar;
}

std::vector<Entry> ReadYamlEntries(const std::string& text, const std::string& path) {
  const YAML::Node root = LoadYaml(text, path);
  if (!root.IsMap()) {
    throw Error(SourceLocation{path, LineOf(root)},
                "expected a map of joint names to values, or name: and position: lists");
  }
  std::vector<Entry> entries;
  for (const auto& pair : root) {
    // a key that is a list or a map (found by fuzzing: its conversion threw yaml-cpp's
    // exception, which left without the file)
    if (!pair.first.IsScalar()) {
      throw Error(SourceLocation{path, LineOf(pair.first)},
                  "expected a joint name as the key, got " + DescribeYaml(pair.first));
    }
    const YAML::Node& value = pair.second;
    Entry entry{pair.first.as<std::string>(), pair.first.Mark().line + 1, value.IsSequence(), {}};
    if (value.IsSequence()) {
      for (const YAML::Node& item : value) {
        entry.items.push_back(ScalarFromText(item.IsScalar() ? item.Scalar() : "(not a scalar)",
                                             item.Mark().line + 1));
      }
    } else {
      entry.items.push_back(ScalarFromText(value.IsScalar() ? value.Scalar() : "(not a scalar)",
                                           value.Mark().line + 1));
    }
    entries.push_back(entry);
  }
  return entries;
}

// nlohmann_json keeps no positions in its values, so a key's line is found in the text: the
// first "key" followed by a colon.
int LineOfJsonKey(const std::string& text, const std::string& key) {
  const std::string quoted = nlohmann::json(key).dump();
  for (size_t at = text.find(quoted); at != std::string::npos; at = text.find(quoted, at + 1)) {
    const size_t after = text.find_first_not_of(" \t\r\n", at + quoted.size());
    if (after != std::string::npos && text[after] == ':') return LineAt(text, at);
  }
  return 0;
}

Scalar ScalarFromJson(const nlohmann::ordered_json& value, int line) {
  if (value.is_number()) return Scalar{value.dump(), true, value.get<double>(), line};
  return Scalar{value.is_string() ? value.get<std::string>() : value.dump(), false, 0, line};
}

std::vector<Entry> ReadJsonEntries(const std::string& text, const std::string& path) {
  const nlohmann::ordered_json root = ParseJson(text, path);
  if (!root.is_object()) {
    throw Error(SourceLocation{path, 1},
                "expected an object of joint names to values, or \"name\" and \"position\" "
                "arrays");
  }
  std::vector<Entry> entries;
  for (const auto& [key, value] : root.items()) {
    const int line = LineOfJsonKey(text, key);
    Entry entry{key, line, value.is_array(), {}};
    if (value.is_array()) {
      for (const nlohmann::ordered_json& item : value) entry.items.push_back(ScalarFromJson(item, line));
    } else {
      entry.items.push_back(ScalarFromJson(value, line));
    }
    entries.push_back(entry);
  }
  return entries;
}

const Entry* FindList(const std::vector<Entry>& entries, const char* key) {
  for (const Entry& entry : entries) {
    if (entry.key == key && entry.is_list) return &entry;
  }
  return nullptr;
}

double NumberFor(const std::string& joint, const Scalar& scalar, const std::string& path) {
  if (!scalar.is_number) {
    throw Error(SourceLocation{path, scalar.line},
                "joint '" + joint + "': expected a number (radians or metres), got '" +
                    scalar.text + "'");
  }
  return scalar.number;
}

// {name: [...], position: [...]} as in sensor_msgs/JointState, or a {name: value} map.
NamedValues Interpret(const std::vector<Entry>& entries, const std::string& path) {
  NamedValues values;
  const Entry* names = FindList(entries, "name");
  const Entry* positions = FindList(entries, "position");
  if (names && positions) {
    if (names->items.size() != positions->items.size()) {
      throw Error(SourceLocation{path, positions->line},
                  "'name' lists " + std::to_string(names->items.size()) + " joints but 'position' " +
                      std::to_string(positions->items.size()) + " values");
    }
    for (size_t i = 0; i < names->items.size(); ++i) {
      const std::string& joint = names->items[i].text;
      values.emplace_back(joint, NumberFor(joint, positions->items[i], path));
    }
    return values;
  }
  for (const Entry& entry : entries) {
    if (entry.is_list) {
      throw Error(SourceLocation{path, entry.line},
                  "joint '" + entry.key + "': expected a number, got a list (a JointState-style " +
                      "file needs both 'name' and 'position' lists)");
    }
    values.emplace_back(entry.key, NumberFor(entry.key, entry.items[0], path));
  }
  return values;
}

bool EndsWith(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() &&
         text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

NamedValues ReadJointFile(const std::string& path) { return ParseJointFile(ReadText(path), path); }

NamedValues ParseJointFile(const std::string& text, const std::string& path) {
  return Interpret(EndsWith(path, ".json") ? ReadJsonEntries(text, path)
                                           : ReadYamlEntries(text, path),
                   path);
}

}  // namespace urdfsnap::model
