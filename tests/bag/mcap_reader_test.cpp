// McapReader on bags from the MCAP project's TypeScript writer: uncompressed, zstd and lz4 chunks,
// no chunks; the topics it reports; and one clear error for each corrupt or truncated file.
#include "bag/mcap_reader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <map>

#include "support/error_text.h"
#include "test_bags.h"

namespace urdfsnap::bag {
namespace {

using test::TestBag;
using ::testing::HasSubstr;

struct Counts {
  std::map<std::string, int> messages;  // by topic
  std::uint64_t last_log_time = 0;
  bool in_order = true;
};

// Reads every message of every topic.
Counts ReadAll(const std::string& path, std::vector<std::string>* topics = nullptr) {
  McapReader reader(path);
  Counts counts;
  reader.ReadMessages([](const McapChannel&) { return true; },
                      [&](const McapMessage& message) {
                        ++counts.messages[message.channel->topic];
                        counts.in_order &= message.log_time >= counts.last_log_time ||
                                           message.channel->topic != "/joint_states";
                        if (message.channel->topic == "/joint_states") {
                          counts.last_log_time = message.log_time;
                        }
                      });
  if (topics) {
    for (const McapChannel* channel : reader.channels()) topics->push_back(channel->topic);
  }
  EXPECT_EQ(reader.profile(), "ros2");
  return counts;
}

class WellFormedBagTest : public ::testing::TestWithParam<const char*> {};

TEST_P(WellFormedBagTest, ReadsEveryMessageOfEveryTopic) {
  std::vector<std::string> topics;
  const Counts counts = ReadAll(TestBag(GetParam()), &topics);
  EXPECT_EQ(counts.messages.at("/joint_states"), 200);
  EXPECT_EQ(counts.messages.at("/tf"), 200);
  EXPECT_EQ(counts.messages.at("/camera/image_raw"), 20);
  EXPECT_TRUE(counts.in_order);
  EXPECT_EQ(topics, (std::vector<std::string>{"/joint_states", "/tf", "/camera/image_raw"}));
}

INSTANTIATE_TEST_SUITE_P(Layouts, WellFormedBagTest,
                         ::testing::Values("joint_states_none.mcap", "joint_states_zstd.mcap",
                                           "joint_states_lz4.mcap", "joint_states_unchunked.mcap"),
                         [](const auto& info) {
                           std::string name = info.param;
                           return name.substr(0, name.find('.'));
                         });

TEST(McapReaderTest, UnwantedChannelsAreNotDelivered) {
  McapReader reader(TestBag("joint_states_zstd.mcap"));
  int delivered = 0;
  reader.ReadMessages([](const McapChannel& channel) { return channel.topic == "/tf"; },
                      [&](const McapMessage& message) {
                        EXPECT_EQ(message.channel->topic, "/tf");
                        EXPECT_EQ(message.channel->schema_name, "tf2_msgs/msg/TFMessage");
                        EXPECT_EQ(message.channel->message_encoding, "cdr");
                        EXPECT_EQ(message.data.size(), 64u);
                        ++delivered;
                      });
  EXPECT_EQ(delivered, 200);
}

TEST(McapReaderTest, CallbackErrorsPassThroughUnchanged) {
  McapReader reader(TestBag("joint_states_lz4.mcap"));
  EXPECT_THROW(reader.ReadMessages([](const McapChannel&) { return true; },
                                   [](const McapMessage&) { throw std::logic_error("mine"); }),
               std::logic_error);
}

struct BadBag {
  const char* file;
  std::vector<const char*> error;  // fragments of the one error message
};

class BadBagTest : public ::testing::TestWithParam<BadBag> {};

TEST_P(BadBagTest, IsOneErrorNamingTheFileAndWhatIsWrong) {
  const std::string path = TestBag(GetParam().file);
  const std::string error = test::ErrorText([&] { ReadAll(path); });
  EXPECT_THAT(error, HasSubstr(path + ": "));
  for (const char* fragment : GetParam().error) EXPECT_THAT(error, HasSubstr(fragment));
}

INSTANTIATE_TEST_SUITE_P(
    CorruptAndTruncated, BadBagTest,
    ::testing::Values(
        BadBag{"corrupt_empty.mcap", {"not an MCAP file"}},
        BadBag{"corrupt_not_mcap.mcap", {"not an MCAP file"}},
        BadBag{"corrupt_truncated_header.mcap", {"truncated MCAP", "mcap recover"}},
        BadBag{"corrupt_truncated_half.mcap", {"truncated MCAP", "does not end with"}},
        BadBag{"corrupt_cut_without_end.mcap", {"truncated MCAP"}},
        BadBag{"corrupt_zstd_data.mcap", {"corrupt MCAP: the chunk at byte", "zstd"}},
        BadBag{"corrupt_lz4_data.mcap", {"corrupt MCAP: the chunk at byte", "lz4"}},
        BadBag{"corrupt_crc.mcap", {"do not match their CRC32"}},
        BadBag{"corrupt_huge_chunk.mcap", {"declares 1099511627776 bytes", "limit of 512 MiB"}},
        BadBag{"corrupt_huge_record.mcap",
               {"truncated MCAP: the Chunk record at byte", "claims 4611686018427387904 bytes"}},
        BadBag{"corrupt_unknown_compression.mcap", {"compressed with 'zztd'", "reads zstd, lz4"}},
        BadBag{"corrupt_no_header.mcap", {"the first record is Schema, not Header"}}),
    [](const auto& info) {
      std::string name = info.param.file;
      return name.substr(0, name.find('.'));
    });

TEST(McapReaderTest, AFolderIsNotAFile) {
  EXPECT_THAT(test::ErrorText([] { McapReader reader(TestBag("split_bag")); }),
              HasSubstr("it is a directory"));
}

}  // namespace
}  // namespace urdfsnap::bag
