// ReadJointStates: the values the TypeScript writer stored in every storage (MCAP files, rosbag2
// folders of MCAP or SQLite files, compressed or not, a bare .db3), split rosbag2 folders, and the
// errors for a bag without the topic, with another type on it, without messages or with a bad
// message.
#include "bag/joint_state_bag.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "bag/rosbag2_folder.h"
#include "support/error_text.h"
#include "test_bags.h"

namespace urdfsnap::bag {
namespace {

using test::TestBag;
using ::testing::ElementsAre;
using ::testing::HasSubstr;

class JointStateValuesTest : public ::testing::TestWithParam<std::pair<const char*, int>> {};

TEST_P(JointStateValuesTest, AreTheOnesWritten) {
  const auto [file, count] = GetParam();
  std::uint64_t expected_index = 1;
  ReadJointStates(TestBag(file), kDefaultJointStateTopic, [&](const BagJointState& state) {
    const int i = static_cast<int>(state.index) - 1;
    ASSERT_EQ(state.index, expected_index++);
    EXPECT_EQ(state.message.StampNanoseconds(), test::BagStamp(i));
    EXPECT_EQ(state.log_time, static_cast<std::uint64_t>(test::BagStamp(i)) + 1'000'000u);
    EXPECT_THAT(state.message.names, ElementsAre("shoulder", "elbow", "wrist"));
    EXPECT_THAT(state.message.positions,
                ElementsAre(test::BagShoulder(i), test::BagElbow(i), test::kBagWrist));
  });
  EXPECT_EQ(expected_index, static_cast<std::uint64_t>(count) + 1);
}

INSTANTIATE_TEST_SUITE_P(Bags, JointStateValuesTest,
                         ::testing::Values(std::pair("joint_states_none.mcap", 200),
                                           std::pair("joint_states_zstd.mcap", 200),
                                           std::pair("joint_states_lz4.mcap", 200),
                                           std::pair("joint_states_unchunked.mcap", 200),
                                           std::pair("joint_states_big_endian.mcap", 50),
                                           // rosbag2 folders split in two, and a bare .db3
                                           std::pair("rosbag2_mcap", 200),
                                           std::pair("rosbag2_sqlite", 200),
                                           std::pair("rosbag2_mcap_file_zstd", 200),
                                           std::pair("rosbag2_mcap_message_zstd", 200),
                                           std::pair("rosbag2_sqlite_file_zstd", 200),
                                           std::pair("joint_states.db3", 100)),
                         [](const auto& info) {
                           std::string name = info.param.first;
                           return name.substr(0, name.find('.'));
                         });

TEST(JointStateBagTest, ReadsBothPublishersOfATopic) {
  int arm = 0, gripper = 0;
  ReadJointStates(TestBag("two_publishers.mcap"), "/joint_states", [&](const BagJointState& state) {
    (state.message.names.size() == 1 ? gripper : arm) += 1;
  });
  EXPECT_EQ(arm, 100);
  EXPECT_EQ(gripper, 50);
}

TEST(JointStateBagTest, ReadsTheFilesOfASplitBagFolderInTheirNumberedOrder) {
  EXPECT_EQ(FindBagFiles(TestBag("split_bag")).files.back().path,
            TestBag("split_bag/split_bag_10.mcap"));
  std::vector<std::int64_t> stamps;
  ReadJointStates(TestBag("split_bag"), "/joint_states", [&](const BagJointState& state) {
    stamps.push_back(state.message.StampNanoseconds());
  });
  ASSERT_EQ(stamps.size(), 55u);
  for (int i = 0; i < 55; ++i) EXPECT_EQ(stamps[i], test::BagStamp(i));
}

struct BadTopic {
  const char* file;
  const char* topic;
  const char* error;
};

class BadTopicTest : public ::testing::TestWithParam<BadTopic> {};

TEST_P(BadTopicTest, IsOneErrorSayingWhy) {
  EXPECT_THAT(test::ErrorText([] {
                ReadJointStates(TestBag(GetParam().file), GetParam().topic,
                                [](const BagJointState&) {});
              }),
              HasSubstr(GetParam().error));
}

INSTANTIATE_TEST_SUITE_P(
    Topics, BadTopicTest,
    ::testing::Values(
        BadTopic{"no_joint_states.mcap", "/joint_states",
                 "no topic '/joint_states' in the bag; its topics are: /camera/image_raw "
                 "(sensor_msgs/msg/Image), /tf (tf2_msgs/msg/TFMessage)"},
        BadTopic{"joint_states_zstd.mcap", "/arm/joint_states", "no topic '/arm/joint_states'"},
        BadTopic{"wrong_type.mcap", "/joint_states",
                 "topic '/joint_states' carries 'std_msgs/msg/String' messages"},
        BadTopic{"no_messages.mcap", "/joint_states", "no messages on '/joint_states'"},
        BadTopic{"garbage_message.mcap", "/joint_states",
                 "garbage_message.mcap: message 1 on '/joint_states' (log time 0.000000005 s): "
                 "not a JointState in CDR: "},
        // SQLite files that are no rosbag2 bags (written by Python's sqlite3 module)
        BadTopic{"bad_not_sqlite.db3", "/joint_states",
                 "bad_not_sqlite.db3: not a rosbag2 SQLite file: file is not a database"},
        BadTopic{"bad_no_messages_table.db3", "/joint_states",
                 "bad_no_messages_table.db3: not a rosbag2 SQLite file: no such table: messages"},
        BadTopic{"bad_text_data.db3", "/joint_states",
                 "bad_text_data.db3: not a rosbag2 SQLite file: row 4 of 'messages' holds "
                 "something other than a blob in 'data'"},
        BadTopic{"bad_null_name.db3", "/joint_states",
                 "bad_null_name.db3: not a rosbag2 SQLite file: row 2 of 'topics' holds something "
                 "other than text in 'name'"}),
    [](const auto& info) {
      std::string name = info.param.file;
      return name.substr(0, name.find('.')) + (info.index == 1 ? "_other_topic" : "");
    });

TEST(JointStateBagTest, AFolderWithoutBagFilesIsAnError) {
  EXPECT_THAT(test::ErrorText([] { FindBagFiles(URDFSNAP_SOURCE_DIR "/tests/bag"); }),
              HasSubstr("a folder without metadata.yaml, .mcap or .db3 files: not a ROS 2 bag"));
}

}  // namespace
}  // namespace urdfsnap::bag
