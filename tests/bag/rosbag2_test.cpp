// rosbag2 as `ros2 bag record` leaves it: folders with metadata.yaml over split MCAP or SQLite
// files, zstd-compressed per file or per message, and bare .db3 files (written by Python's sqlite3
// module, tests/node/write_db3.py), all giving the values written; SQLite files that are no bags
// and metadata that lies are one clear error each.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "bag/joint_state_bag.h"
#include "bag/rosbag2_folder.h"
#include "support/error_text.h"
#include "support/temp_folder.h"
#include "test_bags.h"

namespace urdfsnap::bag {
namespace {

using test::TestBag;
using ::testing::ElementsAre;
using ::testing::HasSubstr;

class Rosbag2ValuesTest : public ::testing::TestWithParam<std::pair<const char*, int>> {};

TEST_P(Rosbag2ValuesTest, AreTheOnesWrittenInOrder) {
  const auto [bag, count] = GetParam();
  int i = 0;
  ReadJointStates(TestBag(bag), kDefaultJointStateTopic, [&](const BagJointState& state) {
    ASSERT_EQ(state.index, static_cast<std::uint64_t>(i) + 1);
    EXPECT_EQ(state.message.StampNanoseconds(), test::BagStamp(i));
    EXPECT_EQ(state.log_time, static_cast<std::uint64_t>(test::BagStamp(i)) + 1'000'000u);
    EXPECT_THAT(state.message.names, ElementsAre("shoulder", "elbow", "wrist"));
    EXPECT_THAT(state.message.positions,
                ElementsAre(test::BagShoulder(i), test::BagElbow(i), test::kBagWrist));
    ++i;
  });
  EXPECT_EQ(i, count);
}

INSTANTIATE_TEST_SUITE_P(Storages, Rosbag2ValuesTest,
                         ::testing::Values(std::pair("rosbag2_mcap", 200),
                                           std::pair("rosbag2_sqlite", 200),
                                           std::pair("rosbag2_mcap_file_zstd", 200),
                                           std::pair("rosbag2_mcap_message_zstd", 200),
                                           std::pair("rosbag2_sqlite_file_zstd", 200),
                                           std::pair("joint_states.db3", 100)),
                         [](const auto& info) {
                           std::string name = info.param.first;
                           return name.substr(0, name.find('.'));
                         });

TEST(Rosbag2Test, MetadataNamesTheFilesAndTheirStorage) {
  const BagLayout layout = FindBagFiles(TestBag("rosbag2_sqlite_file_zstd"));
  ASSERT_EQ(layout.files.size(), 2u);
  EXPECT_EQ(layout.files[1].path,
            TestBag("rosbag2_sqlite_file_zstd/rosbag2_sqlite_file_zstd_1.db3.zstd"));
  EXPECT_EQ(layout.files[1].storage, Storage::kSqlite);
  EXPECT_EQ(layout.compression, Compression::kFile);
}

struct BadBag {
  const char* name;
  const char* bag;
  const char* error;
};

class BadRosbag2Test : public ::testing::TestWithParam<BadBag> {};

TEST_P(BadRosbag2Test, IsOneErrorNamingTheFile) {
  EXPECT_THAT(test::ErrorText([] {
                ReadJointStates(TestBag(GetParam().bag), "/joint_states",
                                [](const BagJointState&) {});
              }),
              HasSubstr(GetParam().error));
}

INSTANTIATE_TEST_SUITE_P(
    Sqlite, BadRosbag2Test,
    ::testing::Values(
        BadBag{"not_sqlite", "bad_not_sqlite.db3",
               "bad_not_sqlite.db3: not a rosbag2 SQLite file: file is not a database"},
        BadBag{"no_messages_table", "bad_no_messages_table.db3",
               "bad_no_messages_table.db3: not a rosbag2 SQLite file: no such table: messages"},
        BadBag{"text_data", "bad_text_data.db3",
               "bad_text_data.db3: not a rosbag2 SQLite file: row 4 of 'messages' holds something "
               "other than a blob in 'data'"},
        BadBag{"blob_name", "bad_null_name.db3",
               "bad_null_name.db3: not a rosbag2 SQLite file: row 2 of 'topics' holds something "
               "other than text in 'name'"}),
    [](const auto& info) { return std::string(info.param.name); });

// A folder with `metadata` as its metadata.yaml and an empty file a.mcap.
std::string FolderWith(const test::TempFolder& folder, const std::string& metadata) {
  std::ofstream(folder.path() / "metadata.yaml") << metadata;
  std::ofstream(folder.path() / "a.mcap");
  return folder.path().string();
}

TEST(Rosbag2Test, BadMetadataIsLocated) {
  const test::TempFolder folder("rosbag2_metadata");
  const std::string path = FolderWith(folder, "");
  const std::string metadata = path + "/metadata.yaml";
  const std::pair<const char*, std::string> cases[] = {
      {"a: [", metadata + ":1: bad YAML"},
      {"other: 1\n", metadata + ":1: expected rosbag2's 'rosbag2_bagfile_information' map"},
      {"rosbag2_bagfile_information:\n  storage_identifier: rosbag_v2\n",
       metadata + ":2: storage_identifier 'rosbag_v2': urdfsnap reads 'mcap' and 'sqlite3' bags"},
      {"rosbag2_bagfile_information:\n  storage_identifier: mcap\n  compression_format: lz4\n",
       metadata + ":3: compression_format 'lz4': urdfsnap reads zstd"},
      {"rosbag2_bagfile_information:\n  storage_identifier: mcap\n  relative_file_paths: [b.mcap]\n",
       metadata + ":3: 'b.mcap': no such file in " + path},
      {"rosbag2_bagfile_information:\n  storage_identifier: mcap\n"
       "  relative_file_paths: [../a.mcap]\n",
       metadata + ":3: '../a.mcap': expected a file in the bag's folder"},
      {"rosbag2_bagfile_information:\n  storage_identifier: sqlite3\n",
       metadata + ":2: storage_identifier 'sqlite3', but the folder holds the other kind of files"},
  };
  for (const auto& [text, error] : cases) {
    SCOPED_TRACE(text);
    FolderWith(folder, text);
    EXPECT_THAT(test::ErrorText([&] { FindBagFiles(path); }), HasSubstr(error));
  }
}

}  // namespace
}  // namespace urdfsnap::bag
