// ffprobe's JSON read with nlohmann_json; ffmpeg's raw RGB frames read from a pipe.
#include "ffmpeg_tools.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>

namespace urdfsnap::test {
namespace {

std::string Quoted(const std::string& text) { return "'" + text + "'"; }

std::string Output(const std::string& command) {
  std::string text;
  std::FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) return text;
  std::array<char, 65536> buffer;
  for (std::size_t n; (n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0;) {
    text.append(buffer.data(), n);
  }
  const int status = ::pclose(pipe);
  EXPECT_EQ(status, 0) << command
                       << " failed (Debian's ffmpeg package, installed by "
                          "scripts/deps.sh, is needed by these tests)";
  return text;
}

}  // namespace

ProbedVideo Probe(const std::string& path) {
  const std::string json = Output(
      "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
      "stream=codec_name,pix_fmt,width,height,r_frame_rate,avg_frame_rate,nb_read_frames,"
      "color_space:format=duration -of json " +
      Quoted(path));
  ProbedVideo video;
  const nlohmann::json root = nlohmann::json::parse(json, nullptr, false);
  if (root.is_discarded() || root["streams"].empty()) {
    ADD_FAILURE() << "ffprobe found no video stream in " << path << ": " << json;
    return video;
  }
  const nlohmann::json& stream = root["streams"][0];
  video.codec = stream.value("codec_name", "");
  video.pixel_format = stream.value("pix_fmt", "");
  video.width = stream.value("width", 0);
  video.height = stream.value("height", 0);
  video.frame_rate = stream.value("r_frame_rate", "");
  video.average_frame_rate = stream.value("avg_frame_rate", "");
  video.frames = std::stoll(stream.value("nb_read_frames", "0"));
  video.color_space = stream.value("color_space", "");
  video.duration = std::stod(root["format"].value("duration", "0"));
  return video;
}

std::vector<image::Image> DecodeFrames(const std::string& path, int width, int height) {
  // -vsync passthrough: every frame the file holds, none duplicated or dropped to fit a rate
  const std::string raw = Output("ffmpeg -v error -i " + Quoted(path) +
                                 " -vsync passthrough -f rawvideo -pix_fmt rgb24 -");
  const std::size_t frame_bytes = std::size_t(width) * height * 3;
  std::vector<image::Image> frames;
  for (std::size_t at = 0; at + frame_bytes <= raw.size(); at += frame_bytes) {
    frames.push_back(
        image::Image{width, height, {raw.begin() + at, raw.begin() + at + frame_bytes}});
  }
  EXPECT_EQ(raw.size() % frame_bytes, 0u) << "a partial frame from " << path;
  return frames;
}

FrameDifference Compare(const image::Image& actual, const image::Image& expected) {
  FrameDifference difference;
  if (actual.rgb.size() != expected.rgb.size() || actual.rgb.empty()) {
    difference.mean = difference.max = difference.percentile_99 = 255;
    return difference;
  }
  std::array<std::size_t, 256> histogram{};
  double sum = 0;
  for (std::size_t i = 0; i < actual.rgb.size(); ++i) {
    const int d = std::abs(int(actual.rgb[i]) - int(expected.rgb[i]));
    ++histogram[d];
    sum += d;
    difference.max = std::max(difference.max, d);
  }
  difference.mean = sum / actual.rgb.size();
  std::size_t count = 0;
  for (int d = 0; d < 256; ++d) {
    count += histogram[d];
    if (count >= actual.rgb.size() * 99 / 100) {
      difference.percentile_99 = d;
      break;
    }
  }
  return difference;
}

}  // namespace urdfsnap::test
