// The real FFmpeg command-line tools (Debian's ffmpeg package, a test-only dependency) as the
// judges of what urdfsnap's encoders write: ffprobe for the stream's facts, ffmpeg to decode every
// frame back to RGB for comparison with what went in.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "image/image.h"

namespace urdfsnap::test {

// What ffprobe says about a file's first video stream (frames counted by decoding them all).
struct ProbedVideo {
  std::string codec;  // "h264", "vp9", "gif"
  std::string pixel_format;
  int width = 0, height = 0;
  std::string frame_rate;          // r_frame_rate, "30/1"
  std::string average_frame_rate;  // avg_frame_rate
  std::int64_t frames = 0;         // nb_read_frames
  double duration = 0;             // the container's, seconds
  std::string color_space;         // "bt709"
};

// Runs ffprobe; fails the test (and returns an empty result) when it cannot.
ProbedVideo Probe(const std::string& path);

// Every frame of the file decoded by ffmpeg to 8-bit RGB at its own size.
std::vector<image::Image> DecodeFrames(const std::string& path, int width, int height);

// How far a decoded frame is from the frame that was encoded, per channel value (0-255).
struct FrameDifference {
  double mean = 0;        // mean absolute difference over all channels
  int percentile_99 = 0;  // 99% of the channel values differ by at most this
  int max = 0;
};
FrameDifference Compare(const image::Image& actual, const image::Image& expected);

}  // namespace urdfsnap::test
