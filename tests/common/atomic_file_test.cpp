// Atomic file writing: the new content appears whole, and on every failure the old file stays as
// it was and no temporary file is left beside it.
#include "common/atomic_file.h"

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "common/error.h"
#include "support/temp_folder.h"

namespace urdfsnap {
namespace {

std::string Contents(const std::string& path) {
  std::ostringstream text;
  text << std::ifstream(path, std::ios::binary).rdbuf();
  return text.str();
}

class AtomicFileTest : public testing::Test {
 protected:
  std::string Path(const std::string& name) const { return folder_.Path(name); }
  std::vector<std::string> Listing() const { return folder_.Listing(); }
  test::TempFolder folder_{"atomic_file_test"};

  // Writes, expects an Error that starts with the path and contains `reason`.
  void ExpectWriteFails(const std::string& path, const std::string& content,
                        const std::string& reason) {
    try {
      WriteFileAtomically(path, content);
      FAIL() << "no error writing " << path;
    } catch (const Error& e) {
      EXPECT_EQ(std::string(e.what()), path + ": cannot write: " + reason);
    }
  }
};

TEST_F(AtomicFileTest, WritesAndReplaces) {
  const std::string path = Path("robot.html");
  WriteFileAtomically(path, "first");
  EXPECT_EQ(Contents(path), "first");
  WriteFileAtomically(path, "second, longer");
  EXPECT_EQ(Contents(path), "second, longer");
  WriteFileAtomically(path, "");
  EXPECT_EQ(Contents(path), "");
  EXPECT_EQ(Listing(), std::vector<std::string>{"robot.html"});
}

TEST_F(AtomicFileTest, FollowsUmaskNotMkstempMode) {
  const mode_t old_mask = ::umask(022);
  WriteFileAtomically(Path("out.png"), "x");
  ::umask(old_mask);
  EXPECT_EQ(std::filesystem::status(Path("out.png")).permissions(), std::filesystem::perms(0644));
}

TEST_F(AtomicFileTest, MissingDirectory) {
  ExpectWriteFails(Path("no/such/dir/out.png"), "x", "No such file or directory");
  EXPECT_TRUE(Listing().empty());
}

TEST_F(AtomicFileTest, TargetIsADirectoryStaysAndNoTemporaryRemains) {
  std::filesystem::create_directory(Path("out.png"));
  ExpectWriteFails(Path("out.png"), "x", "Is a directory");
  EXPECT_TRUE(std::filesystem::is_directory(Path("out.png")));
  EXPECT_EQ(Listing(), std::vector<std::string>{"out.png"});
}

TEST_F(AtomicFileTest, UnwritableDirectoryLeavesExistingFile) {
  if (::geteuid() == 0) GTEST_SKIP() << "root writes into read-only directories";
  WriteFileAtomically(Path("out.png"), "old");
  std::filesystem::permissions(folder_.path(), std::filesystem::perms(0555));
  ExpectWriteFails(Path("out.png"), "new", "Permission denied");
  EXPECT_EQ(Contents(Path("out.png")), "old");
}

// A write that fails half way (here: over the file size limit, which binds root too) leaves the
// old file and no partial temporary file.
TEST_F(AtomicFileTest, FailedWriteLeavesExistingFile) {
  WriteFileAtomically(Path("out.png"), "old");
  rlimit old_limit{};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &old_limit), 0);
  const auto old_handler = std::signal(SIGXFSZ, SIG_IGN);
  rlimit small = old_limit;
  small.rlim_cur = 1000;
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
  ExpectWriteFails(Path("out.png"), std::string(5000, 'n'), "File too large");
  ::setrlimit(RLIMIT_FSIZE, &old_limit);
  std::signal(SIGXFSZ, old_handler);
  EXPECT_EQ(Contents(Path("out.png")), "old");
  EXPECT_EQ(Listing(), std::vector<std::string>{"out.png"});
}

TEST_F(AtomicFileTest, StreamAppearsOnlyWhenCommitted) {
  WriteFileAtomically(Path("out.mp4"), "old");
  {
    AtomicFile file(Path("out.mp4"));
    file.Write("first ");
    file.Write("xecond");
    file.WriteAt(6, "s");
    EXPECT_EQ(Contents(Path("out.mp4")), "old");
    EXPECT_EQ(Listing().size(), 2u);  // the old file and the temporary one beside it
    file.Commit();
  }
  EXPECT_EQ(Contents(Path("out.mp4")), "first second");
  EXPECT_EQ(Listing(), std::vector<std::string>{"out.mp4"});
}

TEST_F(AtomicFileTest, StreamAbandonedWithoutCommitLeavesNothing) {
  {
    AtomicFile file(Path("out.gif"));
    file.Write("half a gif");
  }
  EXPECT_TRUE(Listing().empty());
}

TEST_F(AtomicFileTest, StreamWrittenByAnotherOpenerOfTheTemporaryFile) {
  AtomicFile file(Path("out.webm"));
  std::ofstream(file.temp_path(), std::ios::binary) << "written by a library";
  file.Commit();
  EXPECT_EQ(Contents(Path("out.webm")), "written by a library");
}

TEST_F(AtomicFileTest, StreamIntoAMissingFolderFailsAtOnce) {
  try {
    AtomicFile file(Path("no/such/out.mp4"));
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), Path("no/such/out.mp4") + ": cannot write: No such file or directory");
  }
}

}  // namespace
}  // namespace urdfsnap
