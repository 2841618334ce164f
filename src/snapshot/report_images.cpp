// WriteReportImages: one PNG per image the case has, then the pixels are let go.
#include "snapshot/report_images.h"

#include <filesystem>

#include "image/png_writer.h"

namespace urdfsnap::snapshot {

namespace {

// Writes `image` as DIR/NAME.KIND.png when it has pixels; returns the file name or "".
std::string WriteOne(const std::string& dir, const std::string& name, const char* kind,
                     const image::Image& image) {
  if (image.rgb.empty()) return "";
  const std::string file = name + "." + kind + ".png";
  image::WritePng(image, (std::filesystem::path(dir) / file).string());
  return file;
}

// The pictures of a depth or labels image that did not pass, as NAME.KIND.expected.png, ...
void WriteGray16Pictures(const std::string& dir, const std::string& name, const char* kind,
                         std::optional<Gray16Record>& record, Gray16Result& result) {
  if (record && record->status != CaseStatus::kPassed) {
    const std::string prefix = name + "." + kind;
    record->images.expected = WriteOne(dir, prefix, "expected", result.expected_picture);
    record->images.actual = WriteOne(dir, prefix, "actual", result.actual_picture);
    record->images.diff = WriteOne(dir, prefix, "diff", result.diff_picture);
  }
  result = Gray16Result{};
}

}  // namespace

void WriteReportImages(const std::string& dir, CaseResult& result) {
  CaseRecord& record = result.record;
  if (record.status != CaseStatus::kPassed) {
    record.images.expected = WriteOne(dir, record.name, "expected", result.expected);
    record.images.actual = WriteOne(dir, record.name, "actual", result.actual);
    record.images.diff = WriteOne(dir, record.name, "diff", result.diff);
  }
  result.expected = result.actual = result.diff = image::Image{};
  WriteGray16Pictures(dir, record.name, "depth", record.depth, result.depth);
  WriteGray16Pictures(dir, record.name, "labels", record.labels, result.labels);
}

}  // namespace urdfsnap::snapshot
