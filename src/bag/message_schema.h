// A ROS 2 message definition as field lists: the `ros2msg` text MCAP bags store in their Schema
// records (the type's .msg text, then each type it uses after a line of '=' and "MSG: pkg/Name"),
// or the .msg texts urdfsnap ships for the types it reads (src/bag/msg/), for bags that store no
// definitions (rosbag2's SQLite .db3 files). One schema drives CDR decoding (bag/cdr_message.h)
// whichever the source.
#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace urdfsnap::bag {

// A definition that cannot be read; what() says where ("std_msgs/Header line 2: ...").
class SchemaError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The primitive types of ROS 2 interface definitions (docs.ros.org "Interfaces"), and kMessage for
// a field of another message type.
enum class FieldKind : std::uint8_t {
  kBool, kInt8, kUint8, kInt16, kUint16, kInt32, kUint32, kInt64, kUint64, kFloat32, kFloat64,
  kString, kWstring, kMessage,
};

struct MessageField {
  std::string name;
  FieldKind kind = FieldKind::kInt32;
  int type = -1;  // kMessage: its index in MessageSchema::types()
  enum class Array : std::uint8_t { kNone, kFixed, kSequence } array = Array::kNone;
  std::uint32_t length = 0;  // kFixed: the element count
};

struct MessageType {
  std::string name;  // "std_msgs/Header" (the "/msg/" of ROS 2 names dropped)
  std::vector<MessageField> fields;

  // The index of the field `name`, or -1.
  int FieldIndex(std::string_view name) const;
};

class MessageSchema {
 public:
  // Parses `text` as the definition of `type` ("sensor_msgs/msg/JointState" or
  // "sensor_msgs/JointState"). Comments, constants and default values are skipped. Throws
  // SchemaError for a line that is not a field, a type used but not defined in the text, or a root
  // type that contains itself or nests more than 32 levels deep.
  static MessageSchema Parse(std::string_view type, std::string_view text);

  // The definition urdfsnap ships for `type` with the types it uses, or nothing: builtin_interfaces
  // Time, std_msgs Header and String, sensor_msgs JointState, tf2_msgs TFMessage, geometry_msgs
  // TransformStamped, Transform, Vector3 and Quaternion.
  static std::optional<MessageSchema> Shipped(std::string_view type);

  // The types, the one parsed first, then those it uses.
  const std::vector<MessageType>& types() const { return types_; }
  const MessageType& root() const { return types_.front(); }

 private:
  std::vector<MessageType> types_;
};

// "sensor_msgs/msg/JointState" and "sensor_msgs/JointState" as "sensor_msgs/JointState".
std::string ShortTypeName(std::string_view type);

}  // namespace urdfsnap::bag
