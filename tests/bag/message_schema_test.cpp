// Message definitions: ros2msg text with comments, constants, defaults, arrays, bounds and types
// named within their package; the definitions urdfsnap ships; errors for definitions that cannot
// be; and CDR decoded through them (nested messages, fixed arrays, small integers).
#include "bag/message_schema.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "bag/cdr_message.h"
#include "bag/cdr_reader.h"
#include "support/error_text.h"

namespace urdfsnap::bag {
namespace {

using ::testing::HasSubstr;

// laid out as rosbag2 stores a schema: the type, then each type it uses after a line of '='
constexpr const char* kDefinition = R"(# a header comment
uint8 MODE_A=1        # a constant: not in the data
string FRAME = "map"  # a string constant
std_msgs/Header header
Point[2] corners
int16 small -3        # a default value
string<=8 label
float32[<=4] weights
================================================================================
MSG: std_msgs/Header
builtin_interfaces/Time stamp
string frame_id
================================================================================
MSG: builtin_interfaces/Time
int32 sec
uint32 nanosec
================================================================================
MSG: test_msgs/Point
float64 x
float64 y
)";

TEST(MessageSchemaTest, ParsesFieldsAndResolvesTypesWithinTheirPackage) {
  const MessageSchema schema = MessageSchema::Parse("test_msgs/msg/Shape", kDefinition);
  const MessageType& shape = schema.root();
  EXPECT_EQ(shape.name, "test_msgs/Shape");
  ASSERT_EQ(shape.fields.size(), 5u);
  EXPECT_EQ(shape.fields[0].name, "header");
  EXPECT_EQ(schema.types()[shape.fields[0].type].name, "std_msgs/Header");
  EXPECT_EQ(shape.fields[1].array, MessageField::Array::kFixed);
  EXPECT_EQ(shape.fields[1].length, 2u);
  EXPECT_EQ(schema.types()[shape.fields[1].type].name, "test_msgs/Point");
  EXPECT_EQ(shape.fields[2].kind, FieldKind::kInt16);
  EXPECT_EQ(shape.fields[3].kind, FieldKind::kString);
  EXPECT_EQ(shape.fields[4].kind, FieldKind::kFloat32);
  EXPECT_EQ(shape.fields[4].array, MessageField::Array::kSequence);
}

TEST(MessageSchemaTest, DecodesCdrThroughTheDefinition) {
  const MessageSchema schema = MessageSchema::Parse("test_msgs/msg/Shape", kDefinition);
  // little-endian CDR: stamp (7, 8), frame_id "m", two points, int16 -3, "ab", one float32
  std::vector<std::uint8_t> cdr = {0, 1, 0, 0};
  const auto put = [&](const void* value, std::size_t size) {
    while ((cdr.size() - 4) % size != 0) cdr.push_back(0);
    const auto* bytes = static_cast<const std::uint8_t*>(value);
    cdr.insert(cdr.end(), bytes, bytes + size);
  };
  const std::int32_t sec = 7;
  const std::uint32_t nanosec = 8, frame_length = 2, label_length = 3, weights = 1;
  const double xy[] = {1, 2, 3, 4};
  const std::int16_t small = -3;
  const float weight = 0.5f;
  put(&sec, 4);
  put(&nanosec, 4);
  put(&frame_length, 4);
  cdr.insert(cdr.end(), {'m', 0});
  for (const double& value : xy) put(&value, 8);
  put(&small, 2);
  put(&label_length, 4);
  cdr.insert(cdr.end(), {'a', 'b', 0});
  put(&weights, 4);
  put(&weight, 4);

  const MessageValue shape = DecodeMessage(schema, cdr);
  EXPECT_EQ(shape["header"]["stamp"]["sec"].number, 7);
  EXPECT_EQ(shape["header"]["stamp"]["nanosec"].number, 8);
  EXPECT_EQ(shape["header"]["frame_id"].text, "m");
  ASSERT_EQ(shape["corners"].items.size(), 2u);
  EXPECT_EQ(shape["corners"].items[1]["y"].number, 4);
  EXPECT_EQ(shape["small"].number, -3);
  EXPECT_EQ(shape["label"].text, "ab");
  ASSERT_EQ(shape["weights"].items.size(), 1u);
  EXPECT_EQ(shape["weights"].items[0].number, 0.5);
  EXPECT_THAT(test::ErrorText<CdrError>([&] { (void)shape["missing"]; }),
              HasSubstr("the definition of test_msgs/Shape has no field 'missing'"));
  cdr.pop_back();  // the float32 cut short: its sequence can no longer hold it
  EXPECT_THAT(test::ErrorText<CdrError>([&] { DecodeMessage(schema, cdr); }),
              HasSubstr("a sequence of 1 elements at byte 68, more than the 3 bytes left"));
}

TEST(MessageSchemaTest, ShipsTheDefinitionsOfTheTypesUrdfsnapReads) {
  for (const char* type :
       {"sensor_msgs/msg/JointState", "tf2_msgs/msg/TFMessage", "std_msgs/msg/String",
        "geometry_msgs/msg/TransformStamped", "sensor_msgs/msg/PointCloud2", "sensor_msgs/msg/LaserScan",
        "sensor_msgs/msg/Image", "sensor_msgs/msg/CameraInfo", "visualization_msgs/msg/MarkerArray",
        "nav_msgs/msg/Path", "geometry_msgs/msg/PoseArray", "geometry_msgs/msg/PoseStamped"}) {
    SCOPED_TRACE(type);
    const std::optional<MessageSchema> schema = MessageSchema::Shipped(type);
    ASSERT_TRUE(schema.has_value());
    EXPECT_EQ(schema->root().name, ShortTypeName(type));
  }
  const MessageSchema tf = *MessageSchema::Shipped("tf2_msgs/msg/TFMessage");
  const MessageType& stamped = tf.types()[tf.root().fields[0].type];
  EXPECT_EQ(stamped.name, "geometry_msgs/TransformStamped");
  const MessageType& transform = tf.types()[stamped.fields[2].type];
  EXPECT_EQ(tf.types()[transform.fields[1].type].name, "geometry_msgs/Quaternion");
  const MessageSchema info = *MessageSchema::Shipped("sensor_msgs/msg/CameraInfo");
  EXPECT_EQ(info.types()[info.root().fields.back().type].name, "sensor_msgs/RegionOfInterest");
  EXPECT_FALSE(MessageSchema::Shipped("sensor_msgs/msg/Imu").has_value());
}

TEST(MessageSchemaTest, EmptyMessagesHoldRosidlsPlaceholderByte) {
  const MessageSchema schema = MessageSchema::Parse("std_msgs/msg/Empty", "# nothing\n");
  ASSERT_EQ(schema.root().fields.size(), 1u);
  EXPECT_EQ(schema.root().fields[0].kind, FieldKind::kUint8);
}

TEST(MessageSchemaTest, DefinitionsThatCannotBeAreErrorsSayingWhere) {
  const std::pair<const char*, const char*> cases[] = {
      {"float64\n", "a/B line 1: expected a type and a field name: 'float64'"},
      {"int32[x] values\n", "a/B line 1: a bad array size: 'int32[x] values'"},
      {"Missing thing\n", "a/B: field 'thing' has type 'Missing', which the definition does not define"},
      {"int32 x\n===\nnot a type line\n", "line 3: expected 'MSG: package/Type' after a line of '='"},
      {"a/C c\n===\nMSG: a/C\na/B b\n", "a/B contains itself"},
  };
  for (const auto& [text_, error] : cases) {
    const char* text = text_;   // a plain variable: clang 14 cannot capture a structured binding
    SCOPED_TRACE(text);
    EXPECT_THAT(test::ErrorText<SchemaError>([&] { MessageSchema::Parse("a/msg/B", text); }),
                HasSubstr(error));
  }
  // a chain of 40 types, each holding the next
  std::string deep = "a/T1 next\n";
  for (int i = 1; i < 40; ++i) {
    deep += "===\nMSG: a/T" + std::to_string(i) + "\na/T" + std::to_string(i + 1) + " next\n";
  }
  deep += "===\nMSG: a/T40\nint32 end\n";
  EXPECT_THAT(test::ErrorText<SchemaError>([&] { MessageSchema::Parse("a/msg/B", deep); }),
              HasSubstr("nests types deeper than 32 levels"));
}

}  // namespace
}  // namespace urdfsnap::bag
