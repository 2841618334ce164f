// rosbag2 folders as `ros2 bag record` leaves them: metadata.yaml naming the files, their storage
// and compression, and one located error for metadata that cannot be followed. (The values of each
// storage, and SQLite files that are no bags, are checked beside the MCAP files' in
// joint_state_bag_test.cpp.)
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "bag/rosbag2_folder.h"
#include "support/error_text.h"
#include "support/temp_folder.h"
#include "test_bags.h"

namespace urdfsnap::bag {
namespace {

using test::TestBag;
using ::testing::HasSubstr;

TEST(Rosbag2Test, MetadataNamesTheFilesAndTheirStorage) {
  const BagLayout layout = FindBagFiles(TestBag("rosbag2_sqlite_file_zstd"));
  ASSERT_EQ(layout.files.size(), 2u);
  EXPECT_EQ(layout.files[1].path,
            TestBag("rosbag2_sqlite_file_zstd/rosbag2_sqlite_file_zstd_1.db3.zstd"));
  EXPECT_EQ(layout.files[1].storage, Storage::kSqlite);
  EXPECT_EQ(layout.compression, Compression::kFile);
}

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
