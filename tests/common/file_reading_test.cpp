// ReadFileBounded: whole files, pipes and devices up to a limit, with the system's reasons.
#include "common/file_reading.h"

#include <gtest/gtest.h>

#include <cerrno>
#include <filesystem>
#include <fstream>

#include "support/temp_folder.h"

namespace urdfsnap {
namespace {

namespace fs = std::filesystem;

class FileReadingTest : public ::testing::Test {
 protected:
  std::string Write(const std::string& name, const std::string& bytes) const {
    return folder_.Write(name, bytes);
  }
  test::TempFolder folder_{"file_reading"};
};

// The reason and errno ReadFileBounded throws for `path`, or "no error".
std::pair<std::string, int> Failure(const std::string& path, std::size_t limit) {
  try {
    ReadFileBounded(path, limit);
  } catch (const FileReadError& e) {
    return {e.what(), e.errno_value};
  }
  return {"no error", -1};
}

TEST_F(FileReadingTest, ReadsEveryByte) {
  std::string bytes(200000, 'x');
  bytes[0] = '\0';
  bytes.back() = '\xff';
  EXPECT_EQ(ReadFileBounded(Write("a.bin", bytes)), bytes);
  EXPECT_EQ(ReadFileBounded(Write("empty", "")), "");
}

TEST_F(FileReadingTest, AFileOfExactlyTheLimitIsRead) {
  const std::string bytes(1 << 20, 'y');
  EXPECT_EQ(ReadFileBounded(Write("a.bin", bytes), bytes.size()), bytes);
  EXPECT_EQ(Failure(Write("b.bin", bytes + "z"), bytes.size()),
            std::make_pair(std::string("larger than the limit of 1 MiB"), 0));
}

TEST_F(FileReadingTest, EndlessDevicesStopAtTheLimit) {
  EXPECT_EQ(Failure("/dev/zero", 4 << 20).first, "larger than the limit of 4 MiB");
}

TEST_F(FileReadingTest, SystemErrorsKeepTheirReasonAndErrno) {
  EXPECT_EQ(Failure(folder_.Path("missing"), 100),
            std::make_pair(std::string("No such file or directory"), ENOENT));
  EXPECT_EQ(Failure(folder_.path().string(), 100), std::make_pair(std::string("Is a directory"), EISDIR));
}

}  // namespace
}  // namespace urdfsnap
