// FileWatcher notices edits in place, saves by rename, deletions and files that appear.
#include "serve/file_watcher.h"

#include <filesystem>
#include <fstream>
#include <thread>

#include <gtest/gtest.h>

#include "support/temp_folder.h"

namespace urdfsnap::serve {
namespace {

class FileWatcherTest : public ::testing::Test {
 protected:
  test::TempFolder folder_{"file_watcher"};
  FileWatcher watcher_;
};

TEST_F(FileWatcherTest, NothingChangedNothingReported) {
  const std::string a = folder_.Write("a.urdf", "<robot/>");
  EXPECT_FALSE(watcher_.Watch({a}));
  EXPECT_FALSE(watcher_.Changed());
  EXPECT_EQ(watcher_.files(), std::vector<std::string>{a});
}

TEST_F(FileWatcherTest, EditInPlaceOfTheSameSize) {
  const std::string a = folder_.Write("a.urdf", "<robot name='a'/>");
  watcher_.Watch({a});
  // a later modification time (the file systems here keep nanoseconds; a second apart is safe)
  std::filesystem::last_write_time(a, std::filesystem::last_write_time(a) + std::chrono::seconds(1));
  std::ofstream(a, std::ios::in | std::ios::out) << "<robot name='b'/>";
  EXPECT_TRUE(watcher_.Changed());
  EXPECT_FALSE(watcher_.Changed());  // the new state is the reference now
}

TEST_F(FileWatcherTest, SaveByRenameDeleteAndCreate) {
  const std::string a = folder_.Write("a.urdf", "<robot/>");
  const std::string missing = folder_.Path("mesh.stl");
  watcher_.Watch({a, missing});
  // an editor's save: a new file renamed over the old one (a new inode, perhaps the same time)
  const std::string tmp = folder_.Write("a.urdf.tmp", "<robot/>");
  std::filesystem::rename(tmp, a);
  EXPECT_TRUE(watcher_.Changed());
  folder_.Write("mesh.stl", "solid x\nendsolid x\n");
  EXPECT_TRUE(watcher_.Changed());
  std::filesystem::remove(a);
  EXPECT_TRUE(watcher_.Changed());
}

TEST_F(FileWatcherTest, WatchReportsAChangeSinceTheLastLook) {
  const std::string a = folder_.Write("a.urdf", "<robot/>");
  const std::string b = folder_.Write("b.urdf", "<robot/>");
  watcher_.Watch({a});
  folder_.Write("a.urdf", "<robot name='changed while loading'/>");
  EXPECT_TRUE(watcher_.Watch({a, b}));   // a changed after the last look
  EXPECT_FALSE(watcher_.Watch({a, b}));  // b is new: nothing to compare with
}

}  // namespace
}  // namespace urdfsnap::serve
