// Depth and label sequences: pattern checks, render's file formats as bytes, the names file.
#include "animation/sequence_outputs.h"

#include <filesystem>
#include <regex>

#include "common/error.h"
#include "image/gray16_png.h"
#include "image/npy_writer.h"
#include "render/frame_files.h"
#include "video/frame_pattern.h"

namespace urdfsnap::animation {

namespace {

void CheckPattern(const std::string& pattern, const std::string& option) {
  if (!video::FramePattern::IsPattern(pattern)) {
    throw Error(option + " '" + pattern + "': expected a pattern with the frame number, such as " +
                "depth/%05d.png");
  }
  try {
    video::FramePattern checked(pattern);
  } catch (const Error& e) {
    throw Error(option + ": " + e.what());
  }
}

std::string Bytes(const std::vector<std::uint8_t>& bytes) { return {bytes.begin(), bytes.end()}; }

}  // namespace

void CheckDepthPattern(const std::string& pattern, const std::string& option) {
  CheckPattern(pattern, option);
  render::CheckDepthPath(pattern, option);
}

void CheckLabelsPattern(const std::string& pattern, const std::string& option) {
  CheckPattern(pattern, option);
  render::CheckLabelsPath(pattern, option);
}

std::string DepthFileBytes(const image::DepthImage& depth, const std::string& file) {
  if (std::filesystem::path(file).extension() == ".npy") {
    return image::EncodeNpyFloat32(depth.width, depth.height, depth.metres);
  }
  return Bytes(image::EncodeGray16Png(render::DepthMillimetres(depth)));
}

std::string LabelFileBytes(const image::LabelImage& labels) {
  return Bytes(image::EncodeGray16Png({labels.width, labels.height, labels.labels}));
}

std::string LabelNamesPath(const std::string& pattern) {
  const std::filesystem::path path(pattern);
  // the frame number's conversion (FramePattern allows %d or %i, a 0 flag and a width) and the
  // separators around it
  static const std::regex number(R"([-_. ]*%0?[0-9]*[di][-_. ]*)");
  std::string stem = std::regex_replace(path.stem().string(), number, "");
  if (stem.empty()) stem = "labels";
  return (path.parent_path() / (stem + ".json")).string();
}

}  // namespace urdfsnap::animation
