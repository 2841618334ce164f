// Depth and label files: conversions to the stored units, one encoder per format, and the label
// names beside the image.
#include "image/depth_label_files.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "common/atomic_file.h"
#include "common/error.h"
#include "common/file_extension.h"
#include "image/gray16_png.h"
#include "image/image_file_names.h"
#include "image/npy_writer.h"

namespace urdfsnap::image {

namespace {

enum class DepthFormat { kMillimetrePng, kMetreNpy };

// The format of the depth file `path` by its extension (in any letter case), checked as
// CheckImageFileName checks --depth; throws naming `what` and the path.
DepthFormat DepthFormatOf(const std::string& path, const std::string& what) {
  CheckImageFileName(path, ImageKind::kDepth, what);
  return LowerCaseExtension(path) == ".npy" ? DepthFormat::kMetreNpy : DepthFormat::kMillimetrePng;
}

std::string Bytes(const std::vector<std::uint8_t>& bytes) { return {bytes.begin(), bytes.end()}; }

}  // namespace

Gray16Image DepthMillimetres(const DepthImage& depth) {
  Gray16Image mm{depth.width, depth.height, std::vector<std::uint16_t>(depth.metres.size())};
  for (std::size_t i = 0; i < mm.values.size(); ++i) {
    const float metres = depth.metres[i];
    // a surface nearer than half a millimetre still reads as "robot here"
    mm.values[i] = std::isnan(metres) ? 0 : static_cast<std::uint16_t>(std::clamp(std::lround(metres * 1000.0), 1L, 65535L));
  }
  return mm;
}

std::string EncodeDepthFile(const DepthImage& depth, const std::string& path) {
  switch (DepthFormatOf(path, "depth file")) {
    case DepthFormat::kMetreNpy:
      return EncodeNpyFloat32(depth.width, depth.height, depth.metres);
    case DepthFormat::kMillimetrePng:
      break;
  }
  return Bytes(EncodeGray16Png(DepthMillimetres(depth)));
}

std::string EncodeLabels(const LabelImage& labels) {
  return Bytes(EncodeGray16Png({labels.width, labels.height, labels.labels}));
}

std::string LabelNamesFile(const std::string& path) {
  return std::filesystem::path(path).replace_extension(".json").string();
}

void WriteDepthFile(const DepthImage& depth, const std::string& path) {
  WriteFileAtomically(path, EncodeDepthFile(depth, path));
}

std::string LabelNamesJson(const std::vector<std::string>& link_names) {
  nlohmann::ordered_json names = nlohmann::ordered_json::object();
  for (std::size_t i = 0; i < link_names.size(); ++i) names[std::to_string(i + 1)] = link_names[i];
  return names.dump(2) + "\n";
}

void WriteLabelFiles(const LabelImage& labels, const std::vector<std::string>& link_names, const std::string& path) {
  CheckImageFileName(path, ImageKind::kLabels, "labels file");
  WriteFileAtomically(path, EncodeLabels(labels));
  WriteFileAtomically(LabelNamesFile(path), LabelNamesJson(link_names));
}

}  // namespace urdfsnap::image
