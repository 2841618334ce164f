// EncodeFrames: every frame made reaches the file in order, progress is shown as frames finish,
// and an error while making a frame leaves no output.
#include "video/encode_frames.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdio>

#include "ffmpeg_tools.h"
#include "support/error_text.h"
#include "support/temp_folder.h"
#include "synthetic_frames.h"
#include "video/open_frame_encoder.h"

namespace urdfsnap::video {
namespace {

using ::testing::HasSubstr;

TEST(EncodeFramesTest, WritesEveryFrameInOrderWithProgress) {
  test::TempFolder folder("encode_frames");
  const std::string path = folder.Path("robot.mp4");
  Warnings warnings;
  const auto encoder = OpenFrameEncoder(path, {160, 120, 24}, warnings);
  std::FILE* log = std::tmpfile();
  ASSERT_NE(log, nullptr);
  stream::ProgressBar progress(30, "frames", stream::ProgressBar::Display::kAlways, log);
  EncodeFrames(
      30,
      [](std::int64_t k, image::Image& frame) { frame = test::SyntheticFrame(160, 120, int(k)); },
      *encoder, &progress);
  const std::vector<image::Image> frames = test::DecodeFrames(path, 160, 120);
  ASSERT_EQ(frames.size(), 30u);
  // in order: each decoded frame is nearest to the frame of its own number
  for (int k = 0; k < 30; ++k) {
    EXPECT_LT(test::Compare(frames[k], test::SyntheticFrame(160, 120, k)).percentile_99, 40);
  }
  std::rewind(log);
  char text[4096] = {};
  text[std::fread(text, 1, sizeof text - 1, log)] = '\0';
  EXPECT_THAT(text, HasSubstr("30/30 frames"));
  EXPECT_THAT(text, HasSubstr("30 frames in "));
  std::fclose(log);
}

TEST(EncodeFramesTest, AnErrorMakingAFrameLeavesNoOutput) {
  test::TempFolder folder("encode_frames_error");
  Warnings warnings;
  {
    const auto encoder = OpenFrameEncoder(folder.Path("robot.gif"), {64, 48, 10}, warnings);
    EXPECT_EQ(test::ErrorText([&] {
                EncodeFrames(
                    100,
                    [](std::int64_t k, image::Image& frame) {
                      if (k == 40) throw Error("robot.urdf: the renderer failed");
                      frame = test::SyntheticFrame(64, 48, int(k));
                    },
                    *encoder);
              }),
              "robot.urdf: the renderer failed");
  }
  EXPECT_TRUE(folder.Listing().empty());
}

}  // namespace
}  // namespace urdfsnap::video
