// Each encoder's output decoded by the real FFmpeg tools (or libwebp's own decoder for animated
// WebP, which FFmpeg 5 cannot decode): the stream's codec, size, frame count and frame rate as
// asked, and every decoded frame close to the frame that went in. PNG sequences are byte-exact.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <webp/demux.h>

#include <fstream>
#include <iterator>

#include "ffmpeg_tools.h"
#include "image/png_writer.h"
#include "support/temp_folder.h"
#include "synthetic_frames.h"
#include "video/open_frame_encoder.h"

namespace urdfsnap::video {
namespace {

using test::SyntheticFrame;

constexpr int kWidth = 320, kHeight = 240, kFrames = 40;

// The tolerances below must fail a decoder that shows the wrong frame: neighbouring synthetic
// frames differ by more than this at their 99th percentile (the disc moves, the bar turns).
constexpr int kNeighbourPercentile99 = 100;

TEST(SyntheticFramesTest, NeighboursDifferMoreThanAnyToleranceAllows) {
  for (int i = 0; i + 1 < 150; ++i) {
    EXPECT_GE(
        test::Compare(SyntheticFrame(kWidth, kHeight, i), SyntheticFrame(kWidth, kHeight, i + 1))
            .percentile_99,
        kNeighbourPercentile99)
        << "frames " << i << " and " << i + 1;
  }
}

void WriteAnimation(const std::string& path, double fps, int frames = kFrames) {
  Warnings warnings;
  const auto encoder = OpenFrameEncoder(path, {kWidth, kHeight, fps}, warnings);
  for (int i = 0; i < frames; ++i) encoder->Write(SyntheticFrame(kWidth, kHeight, i));
  encoder->Finish();
  EXPECT_TRUE(warnings.empty());
}

struct LossyCase {
  const char* file;
  const char* codec;
  double fps;
  const char* frame_rate;  // as ffprobe writes it
  // tolerances, per channel value, for the decoded frames against the input; see each case
  double max_mean;
  int max_percentile_99;
};

class LossyRoundTripTest : public ::testing::TestWithParam<LossyCase> {
 protected:
  test::TempFolder folder_{"video_round_trip"};
};

TEST_P(LossyRoundTripTest, DecodesToTheFramesWrittenAtTheRateAsked) {
  const LossyCase& format = GetParam();
  const std::string path = folder_.Path(format.file);
  WriteAnimation(path, format.fps);
  EXPECT_EQ(folder_.Listing(), std::vector<std::string>{format.file});  // no temporary files

  const test::ProbedVideo video = test::Probe(path);
  EXPECT_EQ(video.codec, format.codec);
  EXPECT_EQ(video.width, kWidth);
  EXPECT_EQ(video.height, kHeight);
  EXPECT_EQ(video.frames, kFrames);
  EXPECT_EQ(video.frame_rate, format.frame_rate);
  EXPECT_NEAR(video.duration, kFrames / format.fps, 0.02);

  const std::vector<image::Image> frames = test::DecodeFrames(path, kWidth, kHeight);
  ASSERT_EQ(frames.size(), std::size_t{kFrames});
  for (int i = 0; i < kFrames; ++i) {
    const test::FrameDifference difference =
        test::Compare(frames[i], SyntheticFrame(kWidth, kHeight, i));
    EXPECT_LE(difference.mean, format.max_mean) << "frame " << i;
    EXPECT_LE(difference.percentile_99, format.max_percentile_99) << "frame " << i;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Formats, LossyRoundTripTest,
    ::testing::Values(
        // tolerances about 1.5 times what was measured (see kNeighbourPercentile99 for why they
        // still tell frames apart); H.264 at CRF 20 with 4:2:0 chroma: measured mean 1.8, 99th
        // percentile 16 (thin coloured lines lose chroma)
        LossyCase{"robot.mp4", "h264", 20, "20/1", 2.5, 24},
        LossyCase{"fractional_rate.mp4", "h264", 12.5, "25/2", 2.5, 24},
        // VP9 at CRF 32, realtime speed: measured 2.1 and 17
        LossyCase{"robot.webm", "vp9", 20, "20/1", 3.0, 26},
        // GIF: one palette for the whole animation, dithered: measured 0.1 and 3 (these frames
        // have few colours); delays of 5/100 s for 20 frames/s
        LossyCase{"robot.gif", "gif", 20, "20/1", 0.5, 8}),
    [](const auto& info) {
      std::string name = info.param.file;
      return name.substr(0, name.find('.')) + "_" + name.substr(name.find('.') + 1);
    });

TEST(VideoColourTest, Mp4IsTaggedBt709AndYuv420pForBrowsers) {
  test::TempFolder folder("video_colour");
  const std::string path = folder.Path("robot.mp4");
  WriteAnimation(path, 30, 3);
  const test::ProbedVideo video = test::Probe(path);
  EXPECT_EQ(video.pixel_format, "yuv420p");
  EXPECT_EQ(video.color_space, "bt709");
  // faststart: the index (moov) before the frames (mdat), so that a browser plays while loading
  std::ifstream file(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(file)), {});
  ASSERT_NE(bytes.find("moov"), std::string::npos);
  EXPECT_LT(bytes.find("moov"), bytes.find("mdat"));
}

TEST(WebpRoundTripTest, LibwebpDecodesEveryFrameAtItsTime) {
  test::TempFolder folder("video_webp");
  const std::string path = folder.Path("robot.webp");
  // more frames than one segment of the encoder, to check the container joins them
  constexpr int kWebpFrames = 150;
  constexpr double kFps = 30;
  WriteAnimation(path, kFps, kWebpFrames);
  std::ifstream file(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(file)), {});
  const WebPData data{reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()};
  WebPAnimDecoderOptions options;
  ASSERT_TRUE(WebPAnimDecoderOptionsInit(&options));
  options.color_mode = MODE_RGBA;
  WebPAnimDecoder* decoder = WebPAnimDecoderNew(&data, &options);
  ASSERT_NE(decoder, nullptr) << "libwebp cannot read the file";
  WebPAnimInfo info;
  ASSERT_TRUE(WebPAnimDecoderGetInfo(decoder, &info));
  EXPECT_EQ(info.canvas_width, std::uint32_t{kWidth});
  EXPECT_EQ(info.canvas_height, std::uint32_t{kHeight});
  EXPECT_EQ(info.frame_count, std::uint32_t{kWebpFrames});  // the frames all differ: none merged
  EXPECT_EQ(info.loop_count, 0u);
  int index = 0;
  while (WebPAnimDecoderHasMoreFrames(decoder)) {
    std::uint8_t* rgba = nullptr;
    int end_ms = 0;
    ASSERT_TRUE(WebPAnimDecoderGetNext(decoder, &rgba, &end_ms));
    // frame i is shown until the next frame's time, rounded to milliseconds
    EXPECT_EQ(end_ms, std::lround((index + 1) * 1000 / kFps)) << "frame " << index;
    image::Image frame{kWidth, kHeight, std::vector<std::uint8_t>(kWidth * kHeight * 3)};
    for (int p = 0; p < kWidth * kHeight; ++p) {
      for (int c = 0; c < 3; ++c) frame.rgb[3 * p + c] = rgba[4 * p + c];
      EXPECT_EQ(rgba[4 * p + 3], 255) << "transparent pixel in frame " << index;
    }
    // lossy WebP at quality 85, 4:2:0 like the videos: measured mean 1.5, 99th percentile 22
    const test::FrameDifference difference =
        test::Compare(frame, SyntheticFrame(kWidth, kHeight, index));
    EXPECT_LE(difference.mean, 2.2) << "frame " << index;
    EXPECT_LE(difference.percentile_99, 32) << "frame " << index;
    ++index;
  }
  EXPECT_EQ(index, kWebpFrames);
  WebPAnimDecoderDelete(decoder);
}

TEST(PngSequenceTest, EachFrameIsTheBytesRenderWrites) {
  test::TempFolder folder("video_png");
  std::filesystem::create_directory(folder.path() / "frames");
  const std::string pattern = folder.Path("frames/%04d.png");
  WriteAnimation(pattern, 25, 12);
  std::vector<std::string> expected_names;
  for (int i = 0; i < 12; ++i) {
    char name[16];
    std::snprintf(name, sizeof name, "%04d.png", i);
    expected_names.push_back(name);
    std::ifstream file(folder.Path(std::string("frames/") + name), std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(file)), {});
    const std::vector<std::uint8_t> png = image::EncodePng(SyntheticFrame(kWidth, kHeight, i));
    EXPECT_EQ(bytes, std::string(png.begin(), png.end())) << name;
  }
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(folder.path() / "frames")) {
    names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, expected_names);
}

}  // namespace
}  // namespace urdfsnap::video
