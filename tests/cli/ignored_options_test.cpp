// Options of render and animate given where they do nothing: one warning each, in the one wording
// ("OPTION is ignored: WHY"), and the command still does its work (cli).
#include <string>

#include <gtest/gtest.h>

#include "cli_fixture.h"

namespace urdfsnap::cli_test {
namespace {

using IgnoredOptionsTest = CliTest;

TEST_F(IgnoredOptionsTest, RenderSaysWhichOptionsDoNothing) {
  URDFSNAP_REQUIRE_GL();
  const Result r = RunUrdfsnap("render " + kMrm + " -o " + Path("a.png") +
                               " --size 40x30 --mask-dilate 2 --topic /js --description-topic /rd"
                               " --camera-pose 0,0,5,1,0,0,0 --pitch 1");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output,
            "urdfsnap: warning: --topic /js is ignored: it names the joint states of a bag, and there is no --bag\n"
            "urdfsnap: warning: --description-topic /rd is ignored: it names a bag's recorded robot description, "
            "and MODEL gives the robot\n"
            "urdfsnap: warning: --mask-dilate 2 is ignored: it grows --mask, and --mask is not given\n"
            "urdfsnap: warning: --pitch is ignored: the camera (--camera-info, --camera-frame, --camera-pose) "
            "replaces the orbit view\n");
}

TEST_F(IgnoredOptionsTest, AnimateSaysWhichOptionsDoNothing) {
  URDFSNAP_REQUIRE_GL();
  const Result r = RunUrdfsnap("animate " + kMrm + " -o " + Path("a.gif") +
                               " --turntable --duration 0.2 --size 40x30 --clamp --strict-joints --mask-dilate 1");
  EXPECT_EQ(r.status, 0) << r.output;
  for (const std::string warning :
       {"--mask-dilate 1 is ignored: it grows --mask, and --mask is not given\n",
        "--clamp is ignored: it decides how --trajectory's joints are drawn, and there is no --trajectory\n",
        "--strict-joints is ignored: it decides how --trajectory's joints are drawn, and there is no --trajectory\n"}) {
    EXPECT_NE(r.output.find("urdfsnap: warning: " + warning), std::string::npos) << warning << r.output;
  }
}

}  // namespace
}  // namespace urdfsnap::cli_test
