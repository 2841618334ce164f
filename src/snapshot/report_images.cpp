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

}  // namespace

void WriteReportImages(const std::string& dir, CaseResult& result) {
  CaseRecord& record = result.record;
  if (record.status != CaseStatus::kPassed) {
    record.images.expected = WriteOne(dir, record.name, "expected", result.expected);
    record.images.actual = WriteOne(dir, record.name, "actual", result.actual);
    record.images.diff = WriteOne(dir, record.name, "diff", result.diff);
  }
  result.expected = result.actual = result.diff = image::Image{};
}

}  // namespace urdfsnap::snapshot
