// A walk over the definition's fields reading each from the YAML map of its message.
#include "display/message_file.h"

#include <yaml-cpp/yaml.h>

#include "common/error.h"
#include "common/file_reading.h"
#include "common/internal/yaml_section.h"
#include "common/number_text.h"
#include "display/make_display.h"

namespace urdfsnap::display {
namespace {

// A field left out (yaml-cpp gives an invalid node for a missing key) or written empty.
bool Absent(const YAML::Node& node) { return !node.IsDefined() || node.IsNull(); }

class YamlMessageReader {
 public:
  YamlMessageReader(const bag::MessageSchema& schema, std::string path) : schema_(schema), path_(std::move(path)) {}

  bag::MessageValue Message(int type, const YAML::Node& node) const {
    const bag::MessageType& definition = schema_.types()[type];
    const bool present = !Absent(node);
    if (present && !node.IsMap()) Fail(node, "expected a map of " + definition.name + "'s fields");
    if (present) {
      for (const auto& entry : node) {
        if (definition.FieldIndex(entry.first.Scalar()) < 0) {
          Fail(entry.first, "'" + entry.first.Scalar() + "' is not a field of " + definition.name);
        }
      }
    }
    bag::MessageValue value;
    value.type = &definition;
    for (const bag::MessageField& field : definition.fields) {
      value.items.push_back(Field(field, present ? node[field.name] : YAML::Node()));
    }
    return value;
  }

 private:
  bag::MessageValue Field(const bag::MessageField& field, const YAML::Node& node) const {
    if (field.array == bag::MessageField::Array::kNone) return Element(field, node);
    bag::MessageValue list;
    if (Absent(node)) return list;
    if (!node.IsSequence()) Fail(node, "'" + field.name + "': expected a list");
    if (field.array == bag::MessageField::Array::kFixed && node.size() != field.length) {
      Fail(node, "'" + field.name + "': expected " + std::to_string(field.length) + " elements");
    }
    for (const YAML::Node& element : node) list.items.push_back(Element(field, element));
    return list;
  }

  bag::MessageValue Element(const bag::MessageField& field, const YAML::Node& node) const {
    if (field.kind == bag::FieldKind::kMessage) return Message(field.type, node);
    bag::MessageValue value;
    if (Absent(node)) return value;
    if (!node.IsScalar()) Fail(node, "'" + field.name + "': expected a value, got " + DescribeYaml(node));
    const std::string& text = node.Scalar();
    if (field.kind == bag::FieldKind::kString || field.kind == bag::FieldKind::kWstring) {
      value.text = text;
    } else if (field.kind == bag::FieldKind::kBool) {
      if (text != "true" && text != "false") Fail(node, "'" + field.name + "': expected true or false, got '" + text + "'");
      value.number = text == "true" ? 1 : 0;
    } else if (text == "nan" || text == ".nan" || text == "-nan") {
      value.number = std::numeric_limits<double>::quiet_NaN();   // as ros2 topic echo prints NaN
    } else if (!ParseNumber(text, value.number)) {
      Fail(node, "'" + field.name + "': expected a number, got '" + text + "'");
    }
    return value;
  }

  [[noreturn]] void Fail(const YAML::Node& node, const std::string& what) const {
    throw Error(SourceLocation{path_, LineOf(node)}, what);
  }

  const bag::MessageSchema& schema_;
  std::string path_;
};

}  // namespace

MessageFile ReadMessageFile(const std::string& path, const std::string& type) {
  std::optional<bag::MessageSchema> schema = bag::MessageSchema::Shipped(type);
  if (!schema) {
    throw Error(SourceLocation{path, 0}, "urdfsnap has no definition of message type '" + type +
                                             "'; message files may hold " + DrawnMessageTypes());
  }
  std::string text;
  try {
    text = ReadFileBounded(path);
  } catch (const FileReadError& e) {
    throw Error(SourceLocation{path, 0}, std::string("cannot read the message file: ") + e.what());
  }
  std::vector<YAML::Node> documents;
  try {
    documents = YAML::LoadAll(text);
  } catch (const YAML::Exception& e) {
    throw Error(SourceLocation{path, e.mark.line + 1}, "bad YAML: " + e.msg);
  }
  while (!documents.empty() && documents.back().IsNull()) documents.pop_back();   // a trailing "---"
  if (documents.empty()) throw Error(SourceLocation{path, 0}, "holds no message");
  MessageFile file;
  file.schema = std::make_shared<const bag::MessageSchema>(std::move(*schema));
  file.value = YamlMessageReader(*file.schema, path).Message(0, documents.back());
  return file;
}

}  // namespace urdfsnap::display
