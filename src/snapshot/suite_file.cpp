// ReadSuite: yaml-cpp walks the suite file (located by common's yaml_reader.h); every key of a case is checked where it stands, so an
// error names the suite file and the line of the offending key.
#include "snapshot/suite_file.h"

#include <cstdlib>
#include <filesystem>
#include <set>
#ifdef __GLIBC__
#include <malloc.h>  // malloc_trim
#endif

#include <yaml-cpp/yaml.h>

#include "common/confined_path.h"
#include "common/did_you_mean.h"
#include "common/error.h"
#include "common/file_reading.h"
#include "common/internal/yaml_reader.h"
#include "common/number_text.h"
#include "common/stable_hash.h"

namespace urdfsnap::snapshot {

namespace {

namespace fs = std::filesystem;

class SuiteReader {
 public:
  explicit SuiteReader(const std::string& path)
      : path_(path), dir_(fs::path(path).parent_path()) {}

  Suite Read() {
    std::string text;
    try {
      text = ReadFileBounded(path_);
    } catch (const FileReadError& e) {
      throw Error(SourceLocation{path_, 0}, std::string("cannot read the suite file: ") + e.what());
    }
    YAML::Node root = LoadYaml(text, path_);
    if (!root.IsMap()) throw ErrorAt(root, "expected a map with 'cases:' (and optionally 'defaults:')");
    SnapshotCase defaults;
    YAML::Node cases;
    bool has_cases = false;
    for (const auto& pair : root) {
      const YAML::Node& key_node = pair.first;
      const YAML::Node& value = pair.second;
      const std::string key = key_node.Scalar();
      if (key == "defaults") {
        ApplyKeys(value, defaults, true);
      } else if (key == "cases") {
        cases = value;
        has_cases = true;
      } else {
        throw ErrorAt(key_node, "unknown key '" + key + "' (" + DidYouMean(key, {"defaults", "cases"}) +
                                    "expected 'defaults' or 'cases')");
      }
    }
    if (!has_cases || !cases.IsSequence() || cases.size() == 0) {
      throw ErrorAt(has_cases ? cases : root, "expected 'cases:' with a list of cases");
    }
    Suite suite{path_, StableHashText(text), {}};
    std::set<std::string> names;
    for (const YAML::Node& node : cases) {
      SnapshotCase c = defaults;
      c.index = static_cast<int>(suite.cases.size());
      c.line = LineOf(node);
      ApplyKeys(node, c, false);
      if (c.name.empty()) throw ErrorAt(node, "the case has no 'name'");
      if (!names.insert(c.name).second) throw ErrorAt(node, "a second case named '" + c.name + "'");
      if (c.request.model.path.empty()) throw ErrorAt(node, "case '" + c.name + "' has no 'model'");
      if (c.golden.empty()) c.golden = Resolve(c.name + ".png");
      for (auto [golden, suffix] : {std::pair{&c.depth, ".depth.png"}, std::pair{&c.labels, ".labels.png"}}) {
        if (golden->wanted && golden->golden.empty()) {
          golden->golden = fs::path(c.golden).replace_extension(suffix).string();
        }
      }
      suite.cases.push_back(std::move(c));
    }
    return suite;
  }

 private:
  Error ErrorAt(const YAML::Node& node, const std::string& what) const {
    return Error(SourceLocation{path_, LineOf(node)}, what);
  }

  // A path in the suite is relative to the suite file's folder.
  std::string Resolve(const std::string& path) const {
    if (fs::path(path).is_absolute()) return path;
    return (dir_ / path).lexically_normal().string();
  }

  // A golden's path: `snapshot update` writes it, so it must stay inside the suite's folder (after
  // symbolic links), where a suite from elsewhere cannot make it overwrite another file.
  std::string ResolveGolden(const YAML::Node& value, const std::string& key) const {
    const std::string text = Text(value, key);
    if (ResolveInside(dir_.empty() ? "." : dir_.string(), text).empty()) {
      throw ErrorAt(value, "'" + key + "': '" + text + "' leads outside the suite's folder (goldens are "
                           "written by `snapshot update` and stay beside the suite)");
    }
    return Resolve(text);
  }

  // A scalar, or a list of scalars joined with ',' (focal: [0, 0, 0.5] as --focal 0,0,0.5).
  std::string Text(const YAML::Node& value, const std::string& key) const {
    if (value.IsScalar()) return value.Scalar();
    if (value.IsSequence() && value.size() > 0) {
      std::string text;
      for (const YAML::Node& item : value) {
        if (!item.IsScalar()) break;
        text += (text.empty() ? "" : ",") + item.Scalar();
      }
      if (!text.empty()) return text;
    }
    throw ErrorAt(value, "'" + key + "': expected a value");
  }

  bool Flag(const YAML::Node& value, const std::string& key) const {
    bool flag = false;
    if (!value.IsScalar() || !YAML::convert<bool>::decode(value, flag)) {
      throw ErrorAt(value, "'" + key + "': expected true or false, got '" + Text(value, key) + "'");
    }
    return flag;
  }

  double Number(const YAML::Node& value, const std::string& key, double low, double high) const {
    double number = 0;
    const std::string text = Text(value, key);
    if (!ParseNumber(text, number) || number < low || number > high) {
      throw ErrorAt(value, "'" + key + "': expected a number from " + FormatNumber(low) +
                               " to " + FormatNumber(high) + ", got '" + text + "'");
    }
    return number;
  }

  // A list of scalars (or one scalar) as texts, in file order.
  std::vector<std::string> Texts(const YAML::Node& value, const std::string& key) const {
    if (value.IsScalar()) return {value.Scalar()};
    if (!value.IsSequence()) throw ErrorAt(value, "'" + key + "': expected a list");
    std::vector<std::string> texts;
    for (const YAML::Node& item : value) {
      if (!item.IsScalar()) throw ErrorAt(item, "'" + key + "': expected a list of values");
      texts.push_back(item.Scalar());
    }
    return texts;
  }

  // {KEY: VALUE} as pairs of text, in file order.
  std::vector<std::pair<std::string, std::string>> Pairs(const YAML::Node& value,
                                                         const std::string& key) const {
    if (!value.IsMap()) throw ErrorAt(value, "'" + key + "': expected a map");
    std::vector<std::pair<std::string, std::string>> pairs;
    for (const auto& pair : value) {
      pairs.emplace_back(pair.first.Scalar(), Text(pair.second, key + ": " + pair.first.Scalar()));
    }
    return pairs;
  }

  void ApplyJoints(const YAML::Node& value, request::RenderRequest& request) const {
    if (value.IsScalar()) {
      request.joint_file = Resolve(value.Scalar());
      return;
    }
    if (!value.IsMap()) throw ErrorAt(value, "'joints': expected a map {joint: value} or a joint file");
    for (const auto& pair : value) {
      const std::string name = pair.first.Scalar();
      request.joints.emplace_back(name, Number(pair.second, "joints: " + name, -1e9, 1e9));
    }
  }

  bool ApplyRenderOption(const std::string& key, const YAML::Node& value,
                         request::RenderRequest& request) const {
    for (const request::TextOption& option : request::TextOptions()) {
      if (key != option.name) continue;
      const std::string text = Text(value, key);
      request.*option.field = option.is_path ? Resolve(text) : text;
      return true;
    }
    for (const request::FlagOption& option : request::FlagOptions()) {
      if (key != option.name) continue;
      request.*option.field = Flag(value, key);
      return true;
    }
    return false;
  }

  void ApplyKey(const YAML::Node& key_node, const YAML::Node& value, SnapshotCase& c) const {
    const std::string key = key_node.Scalar();
    request::RenderRequest& r = c.request;
    if (key == "model") {
      r.model.path = Resolve(Text(value, key));
    } else if (key == "args") {
      // a case's argument replaces the default of the same name, the others stay
      for (auto& pair : Pairs(value, key)) {
        // (no structured binding: clang before 16 cannot capture one in a lambda)
        std::erase_if(r.model.xacro_args, [&](const auto& arg) { return arg.first == pair.first; });
        r.model.xacro_args.push_back(std::move(pair));
      }
    } else if (key == "packages") {
      for (const auto& [package, dir] : Pairs(value, key)) r.model.packages[package] = Resolve(dir);
    } else if (key == "xacro-ns") {
      r.model.xacro_ns = Flag(value, key);
    } else if (key == "joints") {
      ApplyJoints(value, r);
    } else if (key == "bag") {
      c.moment.bag = Resolve(Text(value, key));
    } else if (key == "at") {
      c.moment.at = Text(value, key);
    } else if (key == "displays") {
      c.moment.displays = Texts(value, key);
    } else if (key == "max-delta") {
      c.tolerance.max_delta = static_cast<int>(Number(value, key, 0, 255));
    } else if (key == "max-fraction") {
      c.tolerance.max_fraction = Number(value, key, 0, 1);
    } else if (key == "max-mean") {
      c.tolerance.max_mean = Number(value, key, 0, 255);
    } else if (!ApplyGray16Key(key, value, c) && !ApplyRenderOption(key, value, r)) {
      throw ErrorAt(key_node, KnownKeysHint(key));
    }
  }

  // depth, depth-max-delta, depth-max-fraction, labels, labels-max-fraction (the -golden keys belong
  // to a case: ApplyKeys).
  bool ApplyGray16Key(const std::string& key, const YAML::Node& value, SnapshotCase& c) const {
    if (key == "depth" || key == "labels") {
      (key == "depth" ? c.depth : c.labels).wanted = Flag(value, key);
    } else if (key == "depth-max-delta") {
      c.depth.tolerance.max_delta = static_cast<int>(Number(value, key, 0, 65535));
    } else if (key == "depth-max-fraction" || key == "labels-max-fraction") {
      (key == "depth-max-fraction" ? c.depth : c.labels).tolerance.max_fraction = Number(value, key, 0, 1);
    } else {
      return false;
    }
    return true;
  }

  std::string KnownKeysHint(const std::string& key) const {
    std::vector<std::string> keys = {"name", "golden", "model", "args", "packages", "xacro-ns", "joints",
                                     "bag", "at", "displays",
                                     "max-delta", "max-fraction", "max-mean", "depth", "depth-golden",
                                     "depth-max-delta", "depth-max-fraction", "labels", "labels-golden",
                                     "labels-max-fraction"};
    for (const auto& option : request::TextOptions()) keys.push_back(option.name);
    for (const auto& option : request::FlagOptions()) keys.push_back(option.name);
    std::string list;
    for (const std::string& name : keys) list += (list.empty() ? "" : ", ") + name;
    return "unknown key '" + key + "' (" + DidYouMean(key, keys) + "known: " + list + ")";
  }

  void ApplyKeys(const YAML::Node& map, SnapshotCase& c, bool is_defaults) const {
    if (!map.IsMap()) throw ErrorAt(map, is_defaults ? "'defaults': expected a map" : "expected a case: a map with 'name:'");
    std::set<std::string> seen;
    for (const auto& pair : map) {
      const YAML::Node& key_node = pair.first;
      const YAML::Node& value = pair.second;
      const std::string key = key_node.Scalar();
      if (!seen.insert(key).second) throw ErrorAt(key_node, "'" + key + "' is given twice");
      if (key == "name" || key == "golden" || key == "depth-golden" || key == "labels-golden") {
        if (is_defaults) throw ErrorAt(key_node, "'" + key + "' belongs to a case, not to 'defaults'");
        if (key == "golden") {
          c.golden = ResolveGolden(value, key);
        } else if (key != "name") {
          Gray16Golden& golden = key == "depth-golden" ? c.depth : c.labels;
          golden.golden = ResolveGolden(value, key);
          c.option_lines[key] = LineOf(key_node);
        } else if (c.name = Text(value, key); !IsCaseName(c.name)) {
          throw ErrorAt(value, "case name '" + c.name + "': use letters, digits, '_', '-' and '.'");
        }
        continue;
      }
      ApplyKey(key_node, value, c);
      c.option_lines[key] = LineOf(key_node);
    }
    // a golden path asks for the image, unless the case says it does not want it
    for (const char* kind : {"depth", "labels"}) {
      Gray16Golden& golden = std::string(kind) == "depth" ? c.depth : c.labels;
      const std::string path_key = std::string(kind) + "-golden";
      if (!seen.count(path_key)) continue;
      if (seen.count(kind) && !golden.wanted) {
        throw ErrorAt(map[path_key], "'" + path_key + "' given with '" + kind + ": false'");
      }
      golden.wanted = true;
    }
  }

  std::string path_;
  fs::path dir_;
};

}  // namespace

bool IsCaseName(std::string_view name) {
  if (name.empty() || name == "." || name == "..") return false;
  for (char ch : name) {
    if (!std::isalnum(static_cast<unsigned char>(ch)) && ch != '_' && ch != '-' && ch != '.') return false;
  }
  return true;
}

Suite ReadSuite(const std::string& path) {
  // yaml-cpp keeps about 400 bytes per node until its document goes, so a 5,000-case suite parses
  // at about 60 MB, and the cases built among those nodes would pin their pages for the whole run.
  // So the cases are copied once the tree is gone (the copy packs them together, about 2.6 KB a
  // case) and the freed pages are handed back: a suite run's memory stays that of its renderer
  // (bench/suites/suite_memory.py).
  Suite parsed = SuiteReader(path).Read();
  Suite packed = parsed;
  parsed = Suite{};
#ifdef __GLIBC__
  malloc_trim(0);
#endif
  return packed;
}

std::string OptionLocation(const Suite& suite, const SnapshotCase& c, std::string_view name) {
  const auto found = c.option_lines.find(std::string(name));
  const int line = found == c.option_lines.end() ? c.line : found->second;
  return suite.path + ":" + std::to_string(line) + ": " + std::string(name);
}

}  // namespace urdfsnap::snapshot
