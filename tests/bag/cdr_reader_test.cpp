// CDR decoding of JointState (through the definition urdfsnap ships) from bytes made by hand:
// alignment counted from after the encapsulation header, both byte orders, byte arrays kept as
// bytes, and malformed data.
#include "bag/cdr_reader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <bit>
#include <cstring>
#include <vector>

#include "bag/cdr_message.h"
#include "bag/joint_state_message.h"
#include "support/cdr_bytes.h"
#include "support/error_text.h"

namespace urdfsnap::bag {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

using test::CdrBytes;

const MessageSchema& JointStateSchema() {
  static const MessageSchema schema = *MessageSchema::Shipped("sensor_msgs/msg/JointState");
  return schema;
}

CdrBytes JointStateBytes(bool big_endian) {
  CdrBytes cdr(big_endian);
  // stamp, frame_id "base" (4 + 5 bytes: the name list's length then needs 3 bytes of padding)
  cdr.U32(12).U32(345).Str("base");
  cdr.U32(2).Str("shoulder").Str("elbow");
  // the position count ends at a 4-aligned offset; the doubles are padded to 8 from the origin
  cdr.U32(2).F64(0.25).F64(-1.5);
  cdr.U32(0).U32(0);  // velocity, effort
  return cdr;
}

TEST(CdrReaderTest, DecodesAJointStateInEitherByteOrder) {
  for (const bool big_endian : {false, true}) {
    SCOPED_TRACE(big_endian ? "big-endian" : "little-endian");
    JointStateMessage message;
    DecodeJointState(JointStateSchema(), JointStateBytes(big_endian).bytes(), message);
    EXPECT_EQ(message.stamp_sec, 12);
    EXPECT_EQ(message.stamp_nanosec, 345u);
    EXPECT_EQ(message.StampNanoseconds(), 12'000'000'345);
    EXPECT_THAT(message.names, ElementsAre("shoulder", "elbow"));
    EXPECT_THAT(message.positions, ElementsAre(0.25, -1.5));
  }
}

TEST(CdrReaderTest, AlignsFromThePayloadNotTheBuffer) {
  // a uint32 then a float64: 4 bytes of padding between them, counted from after the header
  const std::vector<std::uint8_t> bytes = CdrBytes().U32(7).F64(2.0).bytes();
  ASSERT_EQ(bytes.size(), 4u + 4 + 4 + 8);
  CdrReader reader(bytes);
  EXPECT_EQ(reader.Uint32(), 7u);
  EXPECT_EQ(reader.Float64(), 2.0);
}

// uint8[] and fixed uint8 arrays come out as raw bytes (a PointCloud2's data), the fields around
// them still aligned as CDR lays them out; a byte count beyond the message is an error
TEST(CdrReaderTest, KeepsByteArraysAsBytes) {
  const MessageSchema schema = MessageSchema::Parse("test/Blob", "uint8[] data\nbyte[3] tag\nuint32 after\n");
  const std::vector<std::uint8_t> bytes = CdrBytes().U32(5).Raw({1, 2, 3, 4, 255}).Raw({7, 8, 9}).U32(42).bytes();
  const MessageValue message = DecodeMessage(schema, bytes);
  EXPECT_THAT(message["data"].bytes, ElementsAre(1, 2, 3, 4, 255));
  EXPECT_TRUE(message["data"].items.empty());
  EXPECT_THAT(message["tag"].bytes, ElementsAre(7, 8, 9));
  EXPECT_EQ(message["after"].number, 42);
  const std::vector<std::uint8_t> short_data = CdrBytes().U32(1000).Raw({1, 2, 3}).bytes();
  EXPECT_THAT(test::ErrorText<CdrError>([&] { DecodeMessage(schema, short_data); }),
              HasSubstr("a sequence of 1000 elements"));
}

struct BadCdr {
  const char* name;
  std::vector<std::uint8_t> bytes;
  const char* error;
};

class BadCdrTest : public ::testing::TestWithParam<BadCdr> {};

TEST_P(BadCdrTest, IsACdrErrorSayingWhat) {
  JointStateMessage message;
  EXPECT_THAT(test::ErrorText<CdrError>(
                  [&] { DecodeJointState(JointStateSchema(), GetParam().bytes, message); }),
              HasSubstr(GetParam().error));
}

INSTANTIATE_TEST_SUITE_P(
    Malformed, BadCdrTest,
    ::testing::Values(
        BadCdr{"empty", {}, "too short for CDR's encapsulation header"},
        BadCdr{"xcdr2", {0x00, 0x07, 0x00, 0x00, 1, 0, 0, 0}, "0x0007 (XCDR2)"},
        BadCdr{"parameter_list", {0x00, 0x03, 0x00, 0x00}, "PL_CDR"},
        BadCdr{"cut_in_stamp", CdrBytes().U32(1).Raw({1, 2}).bytes(),
               "runs past the message's end"},
        BadCdr{"string_without_nul", CdrBytes().U32(1).U32(2).U32(3).Raw({'a', 'b', 'c'}).bytes(),
               "no terminating NUL"},
        BadCdr{"huge_name_count", CdrBytes().U32(1).U32(2).Str("").U32(0x7fffffff).bytes(),
               "a sequence of 2147483647 elements"},
        BadCdr{"huge_position_count",
               CdrBytes().U32(1).U32(2).Str("").U32(1).Str("a").U32(100).F64(1).bytes(),
               "a sequence of 100 elements"}),
    [](const ::testing::TestParamInfo<BadCdr>& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace urdfsnap::bag
