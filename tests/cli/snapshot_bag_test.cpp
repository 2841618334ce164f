// Snapshot suite cases that draw a moment of a recording (`bag:`, `at:`, `displays:`, and an .rviz
// file's displays), so that a perception or planning package golden-tests what it publishes: the
// golden is what `render --bag --at --display` draws, a moment that changed fails with a report
// that shows the difference, and 'at' without a bag is an error at its line.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "bag/test_bags.h"
#include "cli_fixture.h"
#include "image/png_reader.h"

namespace urdfsnap::cli_test {
namespace {

class SnapshotBagTest : public CliTest {
 protected:
  void SetUp() override {
    URDFSNAP_REQUIRE_GL();
    CliTest::SetUp();
    std::filesystem::copy_file(test::TestBag("displays_moving.mcap"), Path("run.mcap"));
  }
  // A suite of one case drawing run.mcap at `at` with the cloud and marker displays.
  std::string Suite(const std::string& at) {
    return Write("suite.yaml", "defaults:\n  model: " + kMrm + "\n  size: 320x240\n  distance: 8\n"
                 "  focal: [0.6, 0, 0.8]\ncases:\n  - name: published\n    bag: run.mcap\n    at: " + at +
                 "\n    fixed-frame: odom\n    displays: [MarkerArray:/markers, PointCloud2:/cloud]\n");
  }
};

TEST_F(SnapshotBagTest, TheGoldenIsRenderOfTheMomentAndAChangedMomentFailsWithADiff) {
  const std::string suite = Suite("1.2");
  ASSERT_EQ(RunUrdfsnap("snapshot update " + suite).status, 0);
  const Result render = RunUrdfsnap("render --bag " + Path("run.mcap") + " --at 1.2 " + kMrm +
                                    " --size 320x240 --distance 8 --focal 0.6,0,0.8 --fixed-frame odom "
                                    "--display MarkerArray:/markers --display PointCloud2:/cloud -o " + Path("still.png"));
  ASSERT_EQ(render.status, 0) << render.output;
  EXPECT_EQ(image::ReadPng(Path("published.png")).rgb, image::ReadPng(Path("still.png")).rgb);
  EXPECT_EQ(RunUrdfsnap("snapshot check " + suite).status, 0);

  Suite("1.3");   // the arm and the cloud have moved on
  const Result check = RunUrdfsnap("snapshot check " + suite + " --report " + Path("report"));
  EXPECT_EQ(check.status, 1) << check.output;
  EXPECT_NE(check.output.find("FAILED   published"), std::string::npos) << check.output;
  EXPECT_TRUE(std::filesystem::exists(Path("report/published.diff.png")));
}

TEST_F(SnapshotBagTest, AtWithoutABagIsAnErrorAtItsLine) {
  const std::string suite = Write("suite.yaml", "cases:\n  - name: lost\n    model: " + kMrm + "\n    at: 1\n");
  const Result check = RunUrdfsnap("snapshot check " + suite);
  EXPECT_EQ(check.status, 2) << check.output;
  EXPECT_NE(check.output.find("suite.yaml:4: at: 'at' and 'displays' draw a moment of a recording"), std::string::npos)
      << check.output;
}

}  // namespace
}  // namespace urdfsnap::cli_test
