// Depth and label files: conversions to the stored units and the label names beside the image.
#include "render/frame_files.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "common/atomic_file.h"
#include "common/error.h"
#include "image/gray16_png.h"
#include "image/npy_writer.h"

namespace urdfsnap::render {

namespace {

std::string Extension(const std::string& path) { return std::filesystem::path(path).extension().string(); }

std::string Bytes(const std::vector<std::uint8_t>& bytes) { return {bytes.begin(), bytes.end()}; }

}  // namespace

image::Gray16Image DepthMillimetres(const image::DepthImage& depth) {
  image::Gray16Image mm{depth.width, depth.height, std::vector<std::uint16_t>(depth.metres.size())};
  for (std::size_t i = 0; i < mm.values.size(); ++i) {
    const float metres = depth.metres[i];
    // a surface nearer than half a millimetre still reads as "robot here"
    mm.values[i] = std::isnan(metres) ? 0 : static_cast<std::uint16_t>(std::clamp(std::lround(metres * 1000.0), 1L, 65535L));
  }
  return mm;
}

void CheckDepthPath(const std::string& path, const std::string& option) {
  const std::string extension = Extension(path);
  if (extension != ".png" && extension != ".npy") {
    throw Error(option + " '" + path + "': expected a .png (16-bit millimetres) or .npy (float32 metres) file");
  }
}

void CheckLabelsPath(const std::string& path, const std::string& option) {
  if (Extension(path) != ".png") throw Error(option + " '" + path + "': expected a .png file (16-bit labels)");
}

std::string DepthFileBytes(const image::DepthImage& depth, const std::string& path) {
  CheckDepthPath(path, "depth file");
  if (Extension(path) == ".npy") return image::EncodeNpyFloat32(depth.width, depth.height, depth.metres);
  return Bytes(image::EncodeGray16Png(DepthMillimetres(depth)));
}

std::string LabelFileBytes(const image::LabelImage& labels) {
  return Bytes(image::EncodeGray16Png({labels.width, labels.height, labels.labels}));
}

std::string LabelNamesJson(const model::Robot& robot) {
  nlohmann::ordered_json names = nlohmann::ordered_json::object();
  for (std::size_t i = 0; i < robot.links().size(); ++i) names[std::to_string(i + 1)] = robot.links()[i].name;
  return names.dump(2) + "\n";
}

std::string LabelNamesFile(const std::string& path) {
  return std::filesystem::path(path).replace_extension(".json").string();
}

void WriteDepthFile(const image::DepthImage& depth, const std::string& path) {
  WriteFileAtomically(path, DepthFileBytes(depth, path));
}

void WriteLabelFiles(const image::LabelImage& labels, const model::Robot& robot, const std::string& path) {
  CheckLabelsPath(path, "labels file");
  WriteFileAtomically(path, LabelFileBytes(labels));
  WriteFileAtomically(LabelNamesFile(path), LabelNamesJson(robot));
}

}  // namespace urdfsnap::render
