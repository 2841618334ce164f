// YAML to Python values with PyYAML's YAML 1.1 implicit typing, on top of yaml-cpp.
#include "xacro/internal/yaml_loader.h"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <regex>
#include <unordered_map>

#include "common/file_reading.h"
#include "xacro/internal/evaluation_budget.h"
#include "xacro/internal/number_format.h"
#include "xacro/internal/xml_tree.h"

namespace urdfsnap::xacro {

namespace {

// `start` * `scale` + the value of `digits` in `base` (no sign, no underscores); EvalError when it
// needs more than 127 bits (Python's ints have no bound)
Int YamlDigits(std::string_view digits, int base, const std::string& text, Int start = 0, int scale = 1) {
  Int v = 0;
  const bool overflow_start = __builtin_mul_overflow(start, Int(scale), &start);
  bool overflow = overflow_start;
  for (char c : digits) {
    const int d = std::isdigit(static_cast<unsigned char>(c)) ? c - '0' : std::tolower(c) - 'a' + 10;
    overflow = overflow || __builtin_mul_overflow(v, Int(base), &v) || __builtin_add_overflow(v, Int(d), &v);
  }
  overflow = overflow || __builtin_add_overflow(start, v, &v);
  if (overflow) throw EvalError("integer too large for urdfsnap (more than 127 bits): " + text);
  return v;
}

}  // namespace

Value ResolveYamlScalar(const std::string& text) {
  // PyYAML's resolver patterns (yaml/resolver.py)
  static const std::regex kBool("yes|Yes|YES|no|No|NO|true|True|TRUE|false|False|FALSE|on|On|ON|off|Off|OFF");
  static const std::regex kInt(
      "[-+]?0b[0-1_]+|[-+]?0[0-7_]+|[-+]?(?:0|[1-9][0-9_]*)|[-+]?0x[0-9a-fA-F_]+|[-+]?[1-9][0-9_]*(?::[0-5]?[0-9])+");
  static const std::regex kFloat(
      "[-+]?(?:[0-9][0-9_]*)\\.[0-9_]*(?:[eE][-+][0-9]+)?|\\.[0-9_]+(?:[eE][-+][0-9]+)?|"
      "[-+]?[0-9][0-9_]*(?::[0-5]?[0-9])+\\.[0-9_]*|[-+]?\\.(?:inf|Inf|INF)|\\.(?:nan|NaN|NAN)");
  static const std::regex kNull("~|null|Null|NULL|");
  if (std::regex_match(text, kNull)) return Value::None();
  if (std::regex_match(text, kBool)) {
    const char c = text[0];
    return Value::Bool(c == 'y' || c == 'Y' || c == 't' || c == 'T' || text == "on" || text == "On" || text == "ON");
  }
  std::string clean = text;
  clean.erase(std::remove(clean.begin(), clean.end(), '_'), clean.end());
  if (std::regex_match(text, kInt)) {
    std::string t = clean;
    const bool negative = t[0] == '-';
    if (t[0] == '-' || t[0] == '+') t = t.substr(1);
    Int v = 0;
    if (t.find(':') != std::string::npos) {
      // sexagesimal, YAML 1.1's 1:30 (90)
      size_t k = 0;
      while (k <= t.size()) {
        const size_t e = std::min(t.find(':', k), t.size());
        v = YamlDigits(t.substr(k, e - k), 10, text, v, 60);
        k = e + 1;
      }
    } else if (t.rfind("0b", 0) == 0) {
      v = YamlDigits(t.substr(2), 2, text);
    } else if (t.rfind("0x", 0) == 0) {
      v = YamlDigits(t.substr(2), 16, text);
    } else if (t.size() > 1 && t[0] == '0') {
      v = YamlDigits(t.substr(1), 8, text);
    } else {
      v = YamlDigits(t, 10, text);
    }
    return Value::Integer(negative ? -v : v);
  }
  if (std::regex_match(text, kFloat)) {
    std::string lower = clean;
    for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (lower.find(".inf") != std::string::npos) return Value::Float(lower[0] == '-' ? -HUGE_VAL : HUGE_VAL);
    if (lower.find(".nan") != std::string::npos) return Value::Float(NAN);
    if (lower.find(':') != std::string::npos) {
      const double sign = lower[0] == '-' ? -1.0 : 1.0;
      if (lower[0] == '-' || lower[0] == '+') lower = lower.substr(1);
      double v = 0;
      size_t k = 0;
      while (k <= lower.size()) {
        const size_t e = std::min(lower.find(':', k), lower.size());
        v = v * 60 + std::stod(lower.substr(k, e - k));
        k = e + 1;
      }
      return Value::Float(sign * v);
    }
    return Value::Float(std::strtod(lower.c_str(), nullptr));
  }
  return Value::Str(text);
}

namespace {

// yaml-cpp's nodes to Values. An alias is the node its anchor names, converted once and shared,
// as PyYAML shares the object (ten anchors each aliasing the previous one ten times are ten
// small lists, not ten billion items); every node converted counts against the evaluation
// budget, so no file makes more values than a document may.
class Converter {
 public:
  explicit Converter(const std::function<Value(const std::string&)>& evaluate) : evaluate_(evaluate) {}

  Value Convert(const YAML::Node& node) {
    if (node.Type() != YAML::NodeType::Sequence && node.Type() != YAML::NodeType::Map) return Scalar(node);
    // a node's position in the file is its identity: aliases give the anchored node's
    const auto cached = containers_.find(node.Mark().pos);
    if (cached != containers_.end()) return cached->second;
    EvaluationBudget::Charge(1);
    Value v;
    if (node.Type() == YAML::NodeType::Sequence) {
      ValueList items;
      for (const auto& item : node) items.push_back(Convert(item));
      v = Wrapped(Value::List(std::move(items)), true);
    } else {
      DictBuilder items;
      for (const auto& kv : node) {
        Value key = Convert(kv.first);
        items.Put(std::move(key), Convert(kv.second));
      }
      v = Wrapped(Value::Dict(items.Take()), true);
    }
    containers_.emplace(node.Mark().pos, v);
    return v;
  }

 private:
  Value Scalar(const YAML::Node& node) {
    EvaluationBudget::Charge(1);
    if (node.Type() != YAML::NodeType::Scalar) return Value::None();
    const std::string& tag = node.Tag();
    const std::string& text = node.Scalar();
    if (tag == "!radians" || tag == "!degrees") {
      const Value v = evaluate_(text);
      if (!v.IsNumber()) throw EvalError("invalid expression: " + text);
      const double radians = tag == "!degrees" ? AsDouble(v) * (M_PI / 180.0) : AsDouble(v);
      return Value::Float(radians);
    }
    if (tag == "?") return ResolveYamlScalar(text);  // plain scalar: implicit typing
    if (tag == "tag:yaml.org,2002:int" || tag == "!!int") return ResolveYamlScalar(text);
    if (tag == "tag:yaml.org,2002:float" || tag == "!!float") {
      if (auto f = ParseFloatText(text)) return Value::Float(*f);
    }
    return Value::Str(text);  // quoted or explicitly str-tagged
  }

  const std::function<Value(const std::string&)>& evaluate_;
  std::unordered_map<int, Value> containers_;  // by position in the file
};

}  // namespace

Value LoadYaml(const std::string& path, const std::function<Value(const std::string&)>& evaluate) {
  std::string text;
  try {
    text = ReadFileBounded(path);
  } catch (const FileReadError& e) {
    throw EvalError(PythonOsErrorText(e.errno_value, e.what(), path));
  }
  // the text a document loads counts as text it makes (a yaml file loaded in a loop would
  // otherwise grow without bound)
  EvaluationBudget::ChargeBytes(text.size());
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw EvalError(path + ": invalid YAML: " + e.what());
  }
  return Converter(evaluate).Convert(root);
}

}  // namespace urdfsnap::xacro
