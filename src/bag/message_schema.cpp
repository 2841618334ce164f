// MessageSchema: the text split into sections at "MSG:" lines, each line a field (TYPE NAME, with
// array and bound suffixes) or a constant (TYPE NAME=VALUE, skipped), then type names resolved
// within the text the way rosidl resolves them (a bare name is in the section's own package;
// "Header" is std_msgs/Header) and checked for types that contain themselves.
#include "bag/message_schema.h"

#include <array>
#include <charconv>
#include <utility>

#include "bag/embedded_definitions.h"

namespace urdfsnap::bag {
namespace {

constexpr std::array<std::pair<std::string_view, FieldKind>, 15> kPrimitives = {{
    {"bool", FieldKind::kBool},       {"byte", FieldKind::kUint8},
    {"char", FieldKind::kUint8},      {"int8", FieldKind::kInt8},
    {"uint8", FieldKind::kUint8},     {"int16", FieldKind::kInt16},
    {"uint16", FieldKind::kUint16},   {"int32", FieldKind::kInt32},
    {"uint32", FieldKind::kUint32},   {"int64", FieldKind::kInt64},
    {"uint64", FieldKind::kUint64},   {"float32", FieldKind::kFloat32},
    {"float64", FieldKind::kFloat64}, {"string", FieldKind::kString},
    {"wstring", FieldKind::kWstring},
}};

// The types urdfsnap ships, by name, with the file of src/bag/msg/ holding each.
constexpr std::array<std::string_view, 27> kShippedTypes = {
    "sensor_msgs/JointState",  "std_msgs/Header",       "builtin_interfaces/Time",
    "std_msgs/String",         "tf2_msgs/TFMessage",    "geometry_msgs/TransformStamped",
    "geometry_msgs/Transform", "geometry_msgs/Vector3", "geometry_msgs/Quaternion",
    // the RViz displays' messages (issue 23)
    "visualization_msgs/MarkerArray", "visualization_msgs/Marker", "visualization_msgs/UVCoordinate",
    "visualization_msgs/MeshFile",    "sensor_msgs/CompressedImage", "std_msgs/ColorRGBA",
    "builtin_interfaces/Duration",    "nav_msgs/Path",             "geometry_msgs/PoseArray",
    "geometry_msgs/PoseStamped",      "geometry_msgs/Pose",        "geometry_msgs/Point",
    "sensor_msgs/PointCloud2",        "sensor_msgs/PointField",    "sensor_msgs/LaserScan",
    "sensor_msgs/Image",              "sensor_msgs/CameraInfo",    "sensor_msgs/RegionOfInterest",
};

std::string_view Trimmed(std::string_view text) {
  const std::size_t begin = text.find_first_not_of(" \t\r");
  if (begin == std::string_view::npos) return {};
  return text.substr(begin, text.find_last_not_of(" \t\r") - begin + 1);
}

bool ParseCount(std::string_view text, std::uint32_t& out) {
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), out);
  return error == std::errc() && end == text.data() + text.size() && !text.empty();
}

// One section of the text before its field types are resolved.
struct Section {
  std::string type;
  std::vector<std::string> written;  // each field's base type as written
  std::vector<MessageField> parsed;
};

std::string Package(const std::string& type) { return type.substr(0, type.find('/')); }

// Parses one field line ("float64[] position", "string<=10 name", "uint8[4] bytes") into `section`;
// constants and blank lines add nothing.
void ParseLine(std::string_view line, int number, Section& section) {
  line = Trimmed(line.substr(0, line.find('#')));
  if (line.empty()) return;
  const auto fail = [&](const std::string& what) -> void {
    throw SchemaError(section.type + " line " + std::to_string(number) + ": " + what + ": '" +
                      std::string(line) + "'");
  };
  const std::size_t type_end = line.find_first_of(" \t");
  if (type_end == std::string_view::npos) fail("expected a type and a field name");
  std::string_view type = line.substr(0, type_end);
  const std::string_view rest = Trimmed(line.substr(type_end));
  const std::size_t name_end = rest.find_first_of(" \t=");
  const std::string_view name = rest.substr(0, name_end);
  if (name_end != std::string_view::npos && Trimmed(rest.substr(name_end)).starts_with('=')) {
    return;  // a constant: not in the serialised message
  }
  if (name.empty()) fail("expected a field name");

  MessageField field;
  field.name = std::string(name);
  if (const std::size_t open = type.find('['); open != std::string_view::npos) {
    if (!type.ends_with(']')) fail("expected ']' after the array size");
    std::string_view size = type.substr(open + 1, type.size() - open - 2);
    if (size.empty() || size.starts_with("<=")) {
      field.array = MessageField::Array::kSequence;  // unbounded, or bounded (same encoding)
      if (!size.empty() && !ParseCount(size.substr(2), field.length)) fail("a bad array bound");
      field.length = 0;
    } else {
      field.array = MessageField::Array::kFixed;
      if (!ParseCount(size, field.length)) fail("a bad array size");
    }
    type = type.substr(0, open);
  }
  if (const std::size_t bound = type.find("<="); bound != std::string_view::npos) {
    std::uint32_t ignored = 0;
    if (!ParseCount(type.substr(bound + 2), ignored)) fail("a bad string bound");
    type = type.substr(0, bound);  // string<=N is encoded as string
  }
  field.kind = FieldKind::kMessage;
  for (const auto& [primitive, kind] : kPrimitives) {
    if (primitive == type) field.kind = kind;
  }
  if (type.empty()) fail("expected a type");
  section.written.emplace_back(type);
  section.parsed.push_back(std::move(field));
}

// Deeper nesting than any ROS 2 message has (a JointState is 3 deep): it bounds the decoder's
// recursion for a hostile definition.
constexpr int kMaxNesting = 32;

// Throws when `type` contains itself through its fields (ROS 2 types cannot refer to themselves,
// not even through sequences) or nests deeper than kMaxNesting.
void CheckNesting(const std::vector<MessageType>& types, int type, int depth,
                  std::vector<bool>& open) {
  if (open[type]) throw SchemaError(types[type].name + " contains itself");
  if (depth > kMaxNesting) {
    throw SchemaError(types[type].name + " nests types deeper than " +
                      std::to_string(kMaxNesting) + " levels");
  }
  open[type] = true;
  for (const MessageField& field : types[type].fields) {
    if (field.kind == FieldKind::kMessage) CheckNesting(types, field.type, depth + 1, open);
  }
  open[type] = false;
}

}  // namespace

int MessageType::FieldIndex(std::string_view name) const {
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (fields[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

std::string ShortTypeName(std::string_view type) {
  std::string name(type);
  if (const std::size_t msg = name.find("/msg/"); msg != std::string::npos) name.erase(msg, 4);
  return name;
}

MessageSchema MessageSchema::Parse(std::string_view type, std::string_view text) {
  std::vector<Section> sections(1);
  sections[0].type = ShortTypeName(type);
  int number = 0;
  bool expect_name = false;  // after a line of '=': "MSG: pkg/Name"
  for (std::size_t start = 0; start <= text.size(); ++number) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    const std::string_view line = text.substr(start, end - start);
    start = end + 1;
    const std::string_view trimmed = Trimmed(line);
    if (trimmed.size() >= 3 && trimmed.find_first_not_of('=') == std::string_view::npos) {
      expect_name = true;
      continue;
    }
    if (expect_name) {
      if (trimmed.empty()) continue;
      if (!trimmed.starts_with("MSG:")) {
        throw SchemaError("line " + std::to_string(number + 1) +
                          ": expected 'MSG: package/Type' after a line of '='");
      }
      sections.emplace_back().type = ShortTypeName(Trimmed(trimmed.substr(4)));
      number = 0;
      expect_name = false;
      continue;
    }
    ParseLine(line, number + 1, sections.back());
  }

  MessageSchema schema;
  for (Section& section : sections) {
    // rosidl gives an empty message one byte (rosidl_adapter's
    // "structure_needs_at_least_one_member"), which CDR carries
    if (section.parsed.empty()) {
      section.parsed.push_back({"structure_needs_at_least_one_member", FieldKind::kUint8});
      section.written.emplace_back("uint8");
    }
    schema.types_.push_back({section.type, section.parsed});
  }
  const auto find = [&](const std::string& name) {
    for (std::size_t i = 0; i < sections.size(); ++i) {
      if (sections[i].type == name) return static_cast<int>(i);
    }
    return -1;
  };
  for (std::size_t s = 0; s < sections.size(); ++s) {
    for (std::size_t f = 0; f < sections[s].written.size(); ++f) {
      MessageField& field = schema.types_[s].fields[f];
      if (field.kind != FieldKind::kMessage) continue;
      const std::string& written = sections[s].written[f];
      const std::string name = written.find('/') != std::string::npos ? ShortTypeName(written)
                               : written == "Header" ? "std_msgs/Header"
                                                     : Package(sections[s].type) + "/" + written;
      field.type = find(name);
      if (field.type < 0) {
        throw SchemaError(sections[s].type + ": field '" + field.name + "' has type '" + written +
                          "', which the definition does not define");
      }
    }
  }
  std::vector<bool> open(schema.types_.size(), false);
  CheckNesting(schema.types_, 0, 0, open);
  return schema;
}

std::optional<MessageSchema> MessageSchema::Shipped(std::string_view type) {
  const std::string name = ShortTypeName(type);
  const auto file = [](std::string_view shipped) {
    std::string file(shipped);
    file[file.find('/')] = '.';
    return std::string(EmbeddedDefinition(file + ".msg"));
  };
  bool shipped = false;
  for (std::string_view known : kShippedTypes) shipped = shipped || known == name;
  if (!shipped) return std::nullopt;
  // the type's text, then every other shipped type as a section, as ros2msg schemas are laid out
  std::string text = file(name);
  for (std::string_view other : kShippedTypes) {
    if (other == name) continue;
    text += "================================================================================\nMSG: " +
            std::string(other) + "\n" + file(other);
  }
  return Parse(name, text);
}

}  // namespace urdfsnap::bag
