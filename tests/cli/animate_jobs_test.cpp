// `animate --jobs N` against the binary: a frame sequence drawn by worker processes is the one
// process's sequence byte for byte (colour, depth, labels, masks, keypoints, the link names), with
// one summary line and no temporary file left; a failing worker is the command's one error with
// nothing written; SIGTERM stops the workers and leaves nothing; the command draws beside N-1 workers.
#include <algorithm>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli_fixture.h"

namespace urdfsnap::cli_test {
namespace {

class AnimateJobsTest : public CliTest {
 protected:
  void SetUp() override {
    CliTest::SetUp();
    mrm_ = Write("mrm.urdf", ReadBytes(kMrm));
  }

  // A 1 s turntable of mrm at 10 frames/s into the folder `name`, every per-frame output asked for.
  std::string Animation(const std::string& name) const {
    const std::string folder = Path(name) + "/";
    return "animate " + mrm_ + " --turntable --duration 1 --fps 10 --fit --size 160x120 -o " + folder +
           "%03d.png --depth " + folder + "d%03d.npy --labels " + folder + "l/%03d.png --mask " + folder +
           "m%03d.png --keypoints " + folder + "k%03d.json";
  }

  std::vector<std::string> Listing() const { return folder_->Listing(); }

  std::string mrm_;
};

TEST_F(AnimateJobsTest, WorkersWriteTheSameFilesAsOneProcess) {
  URDFSNAP_REQUIRE_GL();
  Ok(Animation("one") + " --jobs 1");
  // 3 workers, 12 pieces of 11 frames: some pieces are empty
  const Result three = RunUrdfsnap(Animation("three") + " --jobs 3");
  ASSERT_EQ(three.status, 0) << three.output;
  EXPECT_EQ(std::count(three.output.begin(), three.output.end(), '\n'), 1) << three.output;  // the summary
  EXPECT_NE(three.output.find("(frames 0 to 10)"), std::string::npos) << three.output;
  const auto files = FilesBelow(Path("one"));
  EXPECT_EQ(files.size(), 5u * 11u + 1u);   // the link names once
  EXPECT_EQ(FilesBelow(Path("three")), files);
  EXPECT_EQ(Listing(), (std::vector<std::string>{"mrm.urdf", "one", "three"}));
}

// A worker that fails (here: every file past 4 KB refused, as on a full disk) is the command's one
// error line, status 2, and no frame is left.
TEST_F(AnimateJobsTest, AFailingWorkerIsTheCommandsOneError) {
  URDFSNAP_REQUIRE_GL();
  for (const char* jobs : {"1", "2"}) {
    ExpectTheOneFullDiskError("animate " + mrm_ + " --turntable --duration 1 --fps 4 --size 640x480 --jobs " + jobs +
                              " -o " + Path("f/%03d.png"));
    EXPECT_EQ(Listing(), (std::vector<std::string>{"mrm.urdf"}));
  }
}

// SIGTERM to a sequence being drawn by workers stops them, removes their frames and the folder
// made, and ends the command by that signal. With --jobs 2 the command draws beside one worker.
TEST_F(AnimateJobsTest, SigtermStopsTheWorkersAndLeavesNothing) {
  URDFSNAP_REQUIRE_GL();
  ExpectSigtermStopsTheOneWorker("animate " + mrm_ + " --turntable --duration 20 --size 640x480 --jobs 2 -o " +
                                     Path("f/%03d.png"),
                                 Path("f"));
  EXPECT_EQ(Listing(), (std::vector<std::string>{"mrm.urdf"}));
}

}  // namespace
}  // namespace urdfsnap::cli_test
