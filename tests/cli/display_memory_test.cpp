// Memory that does not grow with the length of a bag animated with displays: the same recording
// (tests/node/make_display_bags.mjs: a 10 Hz 2,000-point cloud, a path, markers that live 0.6 s,
// each with a new id) of 10 s and of 60 s, animated with its displays, peak at about the same
// resident set. Keeping every message, or every marker ever received, would add tens of MB.
#include <string>

#include <gtest/gtest.h>

#include "bag/test_bags.h"
#include "cli_fixture.h"
#include "urdfsnap_process.h"
#include "video/ffmpeg_tools.h"

namespace urdfsnap::cli_test {
namespace {

// Peak memory of animating the test bag `name` with its displays at 2 frames/s and 64x48.
long PeakMemoryKb(const std::string& name, const std::string& out) {
  const test::ProcessResult run = test::RunUrdfsnap(
      "animate " + test::TestBag(name) +
      " --fixed-frame odom --display MarkerArray:/markers --display PointCloud2:/cloud --display Path:/path"
      " --size 64x48 --fps 2 -q -o " + out, 300);
  EXPECT_EQ(run.status, 0) << run.err;
  return run.peak_rss_kb;
}

class DisplayMemoryTest : public CliTest {
 protected:
  void SetUp() override {
    URDFSNAP_REQUIRE_GL();
    CliTest::SetUp();
  }
};

TEST_F(DisplayMemoryTest, PeakMemoryDoesNotGrowWithTheBagsLength) {
  if (test::BuiltWithAddressSanitizer()) GTEST_SKIP() << "the sanitizer's own memory hides the figure";
  const long short_run = PeakMemoryKb("displays_10s.mcap", Path("short.mp4"));
  const long long_run = PeakMemoryKb("displays_60s.mcap", Path("long.mp4"));
  // the long bag's clouds alone are 19 MB; its markers 120
  EXPECT_LT(long_run, short_run + 6 * 1024) << short_run << " KB for 10 s, " << long_run << " KB for 60 s";
  EXPECT_EQ(test::Probe(Path("long.mp4")).frames, 121);
}

}  // namespace
}  // namespace urdfsnap::cli_test
