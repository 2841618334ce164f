// Encoder errors: one clear message, given before any frame where it can be, and nothing left
// behind, neither after an error nor when an encoder is abandoned half way.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "support/error_text.h"
#include "support/temp_folder.h"
#include "synthetic_frames.h"
#include "video/frame_encoder.h"
#include "video/open_frame_encoder.h"

namespace urdfsnap::video {
namespace {

using ::testing::HasSubstr;

class EncoderErrorsTest : public ::testing::Test {
 protected:
  std::string Open(const std::string& name, EncoderSettings settings = {64, 48, 10}) {
    return test::ErrorText([&] { OpenFrameEncoder(folder_.Path(name), settings, warnings_); });
  }
  test::TempFolder folder_{"video_errors"};
  Warnings warnings_;
};

TEST_F(EncoderErrorsTest, UnknownFormatsNameTheOnesWritten) {
  EXPECT_THAT(Open("robot.avi"), HasSubstr("robot.avi: unknown animation format '.avi'; urdfsnap "
                                           "writes .mp4, .webm, .gif, .webp, or PNG frames"));
  EXPECT_THAT(Open("robot"), HasSubstr("unknown animation format ''"));
  EXPECT_THAT(Open("f%03d.jpg"), HasSubstr("a numbered frame sequence is written as PNG files"));
  EXPECT_EQ(OutputFormatOf("A.MP4"), OutputFormat::kMp4);
}

TEST_F(EncoderErrorsTest, SizesAFormatCannotHold) {
  EXPECT_THAT(Open("odd.mp4", {641, 480, 30}),
              HasSubstr("odd.mp4: H.264 in 4:2:0 needs an even width and height; 641x480 is odd"));
  EXPECT_THAT(Open("big.webp", {16384, 16, 30}),
              HasSubstr("WebP images are at most 16383 pixels on a side"));
  EXPECT_THAT(Open("none.gif", {0, 10, 30}), HasSubstr("cannot make an animation of 0x10 pixels"));
  EXPECT_THAT(Open("rate.webm", {64, 48, 0}),
              HasSubstr("the frame rate must be a positive number"));
  EXPECT_TRUE(folder_.Listing().empty());
}

TEST_F(EncoderErrorsTest, AnUnwritablePlaceIsAnErrorBeforeAnyFrame) {
  for (const char* name : {"no/such/robot.mp4", "no/such/robot.webm", "no/such/robot.gif",
                           "no/such/robot.webp", "no/such/%05d.png"}) {
    EXPECT_THAT(Open(name), HasSubstr(": cannot write: No such file or directory")) << name;
  }
  EXPECT_TRUE(folder_.Listing().empty());
}

TEST_F(EncoderErrorsTest, AFrameOfAnotherSizeIsAnError) {
  const auto encoder = OpenFrameEncoder(folder_.Path("robot.mp4"), {64, 48, 10}, warnings_);
  EXPECT_THAT(test::ErrorText([&] { encoder->Write(test::SyntheticFrame(32, 48, 0)); }),
              HasSubstr("robot.mp4: a frame of 32x48 in an animation of 64x48"));
}

TEST_F(EncoderErrorsTest, AnAbandonedEncoderLeavesNothing) {
  std::filesystem::create_directory(folder_.path() / "frames");
  for (const char* name :
       {"robot.mp4", "robot.webm", "robot.gif", "robot.webp", "frames/%03d.png"}) {
    {
      const auto encoder = OpenFrameEncoder(folder_.Path(name), {64, 48, 10}, warnings_);
      for (int i = 0; i < 5; ++i) encoder->Write(test::SyntheticFrame(64, 48, i));
    }
    EXPECT_EQ(folder_.Listing(), std::vector<std::string>{"frames"}) << name;
    EXPECT_TRUE(std::filesystem::is_empty(folder_.path() / "frames")) << name;
  }
}

TEST_F(EncoderErrorsTest, AnExistingOutputStaysUntilTheNewOneIsComplete) {
  const std::string path = folder_.Write("robot.gif", "an older animation");
  {
    const auto encoder = OpenFrameEncoder(path, {64, 48, 10}, warnings_);
    encoder->Write(test::SyntheticFrame(64, 48, 0));
  }
  std::ifstream file(path);
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(file), {}), "an older animation");
}

TEST_F(EncoderErrorsTest, OnlyAFrameSequenceStartsPastFrameZero) {
  for (const char* name : {"robot.mp4", "robot.webm", "robot.gif", "robot.webp"}) {
    EXPECT_THAT(Open(name, {64, 48, 10, 7}),
                HasSubstr("file of the whole animation; only a frame sequence (such as "
                          "frames/%05d.png) can start at frame 7")) << name;
  }
  EXPECT_TRUE(folder_.Listing().empty());
}

TEST_F(EncoderErrorsTest, AShardOfASequenceIsNumberedFromItsFirstFrameAndRemovedWhenAbandoned) {
  {
    const auto encoder = OpenFrameEncoder(folder_.Path("%03d.png"), {64, 48, 10, 7}, warnings_);
    for (int i = 0; i < 3; ++i) encoder->Write(test::SyntheticFrame(64, 48, i));
    encoder->Finish();
  }
  EXPECT_EQ(folder_.Listing(), (std::vector<std::string>{"007.png", "008.png", "009.png"}));
  {
    const auto encoder = OpenFrameEncoder(folder_.Path("%03d.png"), {64, 48, 10, 10}, warnings_);
    for (int i = 0; i < 2; ++i) encoder->Write(test::SyntheticFrame(64, 48, i));
  }
  // the abandoned shard took its own files away and left the finished one's
  EXPECT_EQ(folder_.Listing(), (std::vector<std::string>{"007.png", "008.png", "009.png"}));
}

TEST_F(EncoderErrorsTest, ASequenceAppearsWhenFinishedAndAnAbandonedOneLeavesEarlierFilesAlone) {
  folder_.Write("001.png", "an earlier run's frame");
  {
    const auto encoder = OpenFrameEncoder(folder_.Path("%03d.png"), {64, 48, 10}, warnings_);
    for (int i = 0; i < 3; ++i) encoder->Write(test::SyntheticFrame(64, 48, i));
    // written under temporary names: the earlier frame is still there as it was
    EXPECT_EQ(folder_.Listing().size(), 4u);
    EXPECT_FALSE(std::filesystem::exists(folder_.Path("000.png")));
  }
  EXPECT_EQ(folder_.Listing(), std::vector<std::string>{"001.png"});
  EXPECT_EQ(folder_.Read("001.png"), "an earlier run's frame");
  const auto encoder = OpenFrameEncoder(folder_.Path("%03d.png"), {64, 48, 10}, warnings_);
  for (int i = 0; i < 3; ++i) encoder->Write(test::SyntheticFrame(64, 48, i));
  encoder->Finish();
  EXPECT_EQ(folder_.Listing(), (std::vector<std::string>{"000.png", "001.png", "002.png"}));
}

TEST_F(EncoderErrorsTest, FastGifsWarnThatBrowsersSlowThemDown) {
  OpenFrameEncoder(folder_.Path("fast.gif"), {64, 48, 60}, warnings_);
  ASSERT_EQ(warnings_.messages().size(), 1u);
  EXPECT_THAT(warnings_.messages()[0], HasSubstr("browsers show those under 2/100 s as 1/10 s"));
}

}  // namespace
}  // namespace urdfsnap::video
