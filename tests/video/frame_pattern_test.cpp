// Frame name patterns: the names they make and the patterns refused.
#include "video/frame_pattern.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "support/error_text.h"

namespace urdfsnap::video {
namespace {

using ::testing::HasSubstr;

TEST(FramePatternTest, NamesFramesAsPrintfWould) {
  EXPECT_EQ(FramePattern("frames/%05d.png").Name(42), "frames/00042.png");
  EXPECT_EQ(FramePattern("f%d.png").Name(7), "f7.png");
  EXPECT_EQ(FramePattern("f%4i.png").Name(7), "f   7.png");
  EXPECT_EQ(FramePattern("100%%/%03d.png").Name(12345), "100%/12345.png");
}

TEST(FramePatternTest, TellsPatternsFromFileNames) {
  EXPECT_TRUE(FramePattern::IsPattern("frames/%05d.png"));
  EXPECT_TRUE(FramePattern::IsPattern("odd%s.png"));
  EXPECT_FALSE(FramePattern::IsPattern("robot.mp4"));
  EXPECT_FALSE(FramePattern::IsPattern("100%%.gif"));
}

TEST(FramePatternTest, RefusesPatternsWithoutExactlyOneFrameNumber) {
  EXPECT_THAT(
      test::ErrorText([] { FramePattern("a%d_%d.png"); }),
      HasSubstr("a%d_%d.png: a frame sequence needs exactly one frame number such as %05d, not 2"));
  EXPECT_THAT(test::ErrorText([] { FramePattern("a%%.png"); }), HasSubstr("not 0"));
  EXPECT_THAT(test::ErrorText([] { FramePattern("a%s.png"); }),
              HasSubstr("'%s' is not a frame number; use %d or %05d"));
  EXPECT_THAT(test::ErrorText([] { FramePattern("a%5.2d.png"); }),
              HasSubstr("'%5.' is not a frame number"));
  EXPECT_THAT(test::ErrorText([] { FramePattern("a%099d.png"); }),
              HasSubstr("a frame number wider than 12 digits"));
  EXPECT_THAT(test::ErrorText([] { FramePattern("a%"); }), HasSubstr("'%' is not a frame number"));
}

}  // namespace
}  // namespace urdfsnap::video
