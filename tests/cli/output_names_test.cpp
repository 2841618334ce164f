// Image outputs named for another format are refused before anything is drawn, with one line
// naming the extensions; --fit-margin's forms and its warning without --fit; warnings with
// numbers read as people type them (cli).
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "cli_fixture.h"

namespace urdfsnap::cli_test {
namespace {

namespace fs = std::filesystem;

using OutputNamesTest = CliTest;

TEST_F(OutputNamesTest, AnImageNamedForAnotherFormatIsOneErrorAndNothingIsWritten) {
  const Result jpeg = RunUrdfsnap("render " + kMrm + " -o " + Path("pose.jpg"));
  EXPECT_EQ(jpeg.status, 2) << jpeg.output;
  EXPECT_EQ(jpeg.output, "urdfsnap: error: -o '" + Path("pose.jpg") +
                             "': expected a .png (8-bit RGB) file; urdfsnap does not write .jpg images\n");
  const Result diff = RunUrdfsnap("diff " + kMrm + " " + kMrm + " --diff " + Path("d.bmp"));
  EXPECT_EQ(diff.status, 2) << diff.output;
  EXPECT_NE(diff.output.find("--diff '" + Path("d.bmp") + "': expected a .png"), std::string::npos) << diff.output;
  const std::string suite = Write("suite.yaml", "cases:\n  - name: a\n    model: " + kMrm + "\n    golden: a.jpeg\n");
  const Result golden = RunUrdfsnap("snapshot update " + suite);
  EXPECT_EQ(golden.status, 2) << golden.output;
  EXPECT_NE(golden.output.find(suite + ":4: 'golden' 'a.jpeg': expected a .png"), std::string::npos) << golden.output;
  EXPECT_TRUE(fs::is_empty(dir_) || !fs::exists(Path("pose.jpg")));
  EXPECT_FALSE(fs::exists(Path("a.jpeg")));
}

TEST_F(OutputNamesTest, FitMarginTakesAFractionOrPixelsAndWarnsWithoutFit) {
  const Result bad = RunUrdfsnap("render " + kMrm + " -o " + Path("a.png") + " --fit --fit-margin 0.6");
  EXPECT_EQ(bad.status, 2) << bad.output;
  EXPECT_NE(bad.output.find("--fit-margin '0.6': expected a fraction of each side from 0 to 0.45 (e.g. 0.05) "
                            "or pixels from 0px to 239.5px for 640x480 (e.g. 12px)"),
            std::string::npos)
      << bad.output;
  URDFSNAP_REQUIRE_GL();
  const Result pixels = RunUrdfsnap("render " + kMrm + " -o " + Path("a.png") + " --size 80x60 --fit --fit-margin 6px");
  EXPECT_EQ(pixels.status, 0) << pixels.output;
  const Result unused = RunUrdfsnap("render " + kMrm + " -o " + Path("b.png") + " --size 80x60 --fit-margin 6px");
  EXPECT_EQ(unused.status, 0) << unused.output;
  EXPECT_NE(unused.output.find("urdfsnap: warning: --fit-margin 6px is ignored: it is the border --fit leaves, "
                               "and --fit is not given"),
            std::string::npos)
      << unused.output;
}

}  // namespace
}  // namespace urdfsnap::cli_test
