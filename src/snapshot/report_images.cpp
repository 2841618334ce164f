// The report's file names, and WriteReportImages: one PNG per image the case has, then the pixels
// are let go.
#include "snapshot/report_images.h"

#include <filesystem>

#include "image/png_writer.h"

namespace urdfsnap::snapshot {

namespace {

// NAME.expected.png: the image of `kind` of a case's part ("" colour, ".depth", ".labels").
std::string ImageName(const std::string& name, const char* part, const char* kind) {
  return name + part + "." + kind + ".png";
}

constexpr const char* kParts[] = {"", ".depth", ".labels"};
constexpr const char* kKinds[] = {"expected", "actual", "diff"};

// Writes `image` as DIR/NAME.KIND.png when it has pixels; returns the file name or "".
std::string WriteOne(OutputPlan& outputs, const std::string& dir, const std::string& name, const char* part,
                     const char* kind, const image::Image& image) {
  if (image.rgb.empty()) return "";
  const std::string file = ImageName(name, part, kind);
  outputs.Write((std::filesystem::path(dir) / file).string(), image::EncodePng(image));
  return file;
}

// The pictures of a depth or labels image that did not pass, as NAME.KIND.expected.png, ...
void WriteGray16Pictures(OutputPlan& outputs, const std::string& dir, const std::string& name, const char* part,
                         std::optional<Gray16Record>& record, Gray16Result& result) {
  if (record && record->status != CaseStatus::kPassed) {
    record->images.expected = WriteOne(outputs, dir, name, part, "expected", result.expected_picture);
    record->images.actual = WriteOne(outputs, dir, name, part, "actual", result.actual_picture);
    record->images.diff = WriteOne(outputs, dir, name, part, "diff", result.diff_picture);
  }
  result = Gray16Result{};
}

}  // namespace

std::string ReportIndexFile(const std::string& dir) { return (std::filesystem::path(dir) / "index.html").string(); }

std::vector<std::string> ReportImageNames(const std::string& name) {
  std::vector<std::string> names;
  for (const char* part : kParts) {
    for (const char* kind : kKinds) names.push_back(ImageName(name, part, kind));
  }
  return names;
}

void PlanReport(OutputPlan& outputs, const std::string& dir, const std::vector<std::string>& names,
                const std::string& role) {
  outputs.AddFile(ReportIndexFile(dir), role);
  for (const std::string& name : names) {
    for (const std::string& file : ReportImageNames(name)) {
      outputs.AddFile((std::filesystem::path(dir) / file).string(), role);
    }
  }
}

void WriteReportImages(OutputPlan& outputs, const std::string& dir, CaseResult& result) {
  CaseRecord& record = result.record;
  if (record.status != CaseStatus::kPassed) {
    record.images.expected = WriteOne(outputs, dir, record.name, "", "expected", result.expected);
    record.images.actual = WriteOne(outputs, dir, record.name, "", "actual", result.actual);
    record.images.diff = WriteOne(outputs, dir, record.name, "", "diff", result.diff);
  }
  result.expected = result.actual = result.diff = image::Image{};
  WriteGray16Pictures(outputs, dir, record.name, ".depth", record.depth, result.depth);
  WriteGray16Pictures(outputs, dir, record.name, ".labels", record.labels, result.labels);
}

}  // namespace urdfsnap::snapshot
