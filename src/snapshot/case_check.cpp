// CheckCase: one render, one read per golden, one comparison per image; failures become results,
// not exceptions.
#include "snapshot/case_check.h"

#include <chrono>
#include <filesystem>
#include <functional>
#include <memory>
#include <set>

#include "common/error.h"
#include "image/png_reader.h"
#include "image/depth_label_files.h"

namespace urdfsnap::snapshot {

namespace {

// An error from deeper down (a model file, a joint name) gets the case's place in the suite;
// option errors already start with it.
std::string Located(const Suite& suite, const SnapshotCase& c, const std::string& what) {
  if (what.rfind(suite.path + ":", 0) == 0) return what;
  return suite.path + ":" + std::to_string(c.line) + ": case '" + c.name + "': " + what;
}

void Compare(const SnapshotCase& c, CaseResult& result) {
  CaseRecord& record = result.record;
  if (!std::filesystem::exists(c.golden)) {
    record.status = CaseStatus::kMissing;
    record.message = "no golden image " + c.golden;
    return;
  }
  result.expected = image::ReadPng(c.golden);
  if (result.expected.width != result.actual.width || result.expected.height != result.actual.height) {
    record.status = CaseStatus::kFailed;
    record.message = "size differs: golden " + c.golden + " is " + image::SizeText(result.expected) +
                     ", the render is " + image::SizeText(result.actual);
    return;
  }
  const int delta = c.tolerance.max_delta;
  record.figures = image::CompareImages(result.expected, result.actual, delta);
  record.message = image::DescribeDiff(*record.figures, c.tolerance);
  if (image::WithinTolerance(*record.figures, c.tolerance)) {
    record.status = CaseStatus::kPassed;
    return;
  }
  record.status = CaseStatus::kFailed;
  result.diff = image::MakeDiffImage(result.expected, result.actual, delta);
}

const char* KindName(image::Gray16Kind kind) { return kind == image::Gray16Kind::kDepth ? "depth" : "labels"; }

// The viewable picture of `values`; depth coloured over [near, far].
image::Image Picture(image::Gray16Kind kind, const image::Gray16Image& values, int near, int far) {
  return kind == image::Gray16Kind::kDepth ? image::DepthPicture(values, near, far) : image::LabelPicture(values);
}

image::Image Picture(image::Gray16Kind kind, const image::Gray16Image& values) {
  int near = 0, far = 0;
  image::Gray16ValueRange(values, values, near, far);
  return Picture(kind, values, near, far);
}

// ", links link_03, link_04": the links whose labels are at the pixels where `a` and `b` differ.
std::string LinksWhereDiffer(const image::Gray16Image& a, const image::Gray16Image& b, const model::Robot& robot) {
  std::set<int> labels;
  for (std::size_t i = 0; i < a.values.size(); ++i) {
    if (a.values[i] == b.values[i]) continue;
    for (const int label : {int(a.values[i]), int(b.values[i])}) {
      if (label != 0) labels.insert(label);
    }
  }
  std::string names;
  int listed = 0;
  for (const int label : labels) {
    if (++listed > 8) return names + ", ...";
    const bool known = label <= static_cast<int>(robot.links().size());
    names += (names.empty() ? ", links " : ", ") +
             (known ? robot.links()[label - 1].name : "(label " + std::to_string(label) + ", no such link)");
  }
  return names;
}

// Compares the render's depth or labels with `golden`, leaving the report's pictures in `images`.
Gray16Record CompareGray16Golden(const Gray16Golden& golden, image::Gray16Kind kind, Gray16Result& images,
                                 const model::Robot& robot) {
  Gray16Record record{golden.golden, CaseStatus::kFailed, "", golden.tolerance, std::nullopt, {}};
  const image::Gray16Image& actual = images.actual;
  const std::string what = KindName(kind);
  if (!std::filesystem::exists(golden.golden)) {
    record.status = CaseStatus::kMissing;
    record.message = "no " + what + " golden " + golden.golden;
    images.actual_picture = Picture(kind, actual);
    return record;
  }
  const image::Gray16Image expected = image::ReadGray16Png(golden.golden);
  if (expected.width != actual.width || expected.height != actual.height) {
    record.message = "size differs: " + what + " golden " + golden.golden + " is " +
                     image::SizeText(expected.width, expected.height) + ", the render is " +
                     image::SizeText(actual.width, actual.height);
    images.expected_picture = Picture(kind, expected);
    images.actual_picture = Picture(kind, actual);
    return record;
  }
  record.figures = image::CompareGray16(expected, actual, kind, golden.tolerance.max_delta);
  record.message = image::DescribeGray16Diff(*record.figures, golden.tolerance, kind);
  if (kind == image::Gray16Kind::kLabels && record.figures->pixels_over > 0) {
    record.message += LinksWhereDiffer(expected, actual, robot);
  }
  if (image::WithinTolerance(*record.figures, golden.tolerance)) {
    record.status = CaseStatus::kPassed;
    return record;
  }
  int near = 0, far = 0;  // one range for both, so that a colour means one depth in each
  image::Gray16ValueRange(expected, actual, near, far);
  images.expected_picture = Picture(kind, expected, near, far);
  images.actual_picture = Picture(kind, actual, near, far);
  images.diff_picture = image::MakeGray16DiffImage(expected, actual, golden.tolerance.max_delta, images.expected_picture);
  return record;
}

// The depth and labels comparisons of a rendered case, then the case's status and message from all.
void CompareGray16Goldens(const SnapshotCase& c, image::Frame& frame, CaseResult& result,
                          const model::Robot& robot) {
  CaseRecord& record = result.record;
  if (c.depth.wanted) {
    result.depth.actual = image::DepthMillimetres(frame.depth);
    record.depth = CompareGray16Golden(c.depth, image::Gray16Kind::kDepth, result.depth, robot);
  }
  if (c.labels.wanted) {
    image::LabelImage& labels = frame.labels;
    result.labels.actual = image::Gray16Image{labels.width, labels.height, std::move(labels.labels)};
    record.labels = CompareGray16Golden(c.labels, image::Gray16Kind::kLabels, result.labels, robot);
  }
  const std::optional<Gray16Record>* parts[] = {&record.depth, &record.labels};
  for (const std::optional<Gray16Record>* part : parts) {
    if (!*part) continue;
    record.status = CombinedStatus({record.status, (*part)->status});
    record.message += std::string("; ") + (part == &record.depth ? "depth" : "labels") + ": " + (*part)->message;
  }
}

}  // namespace

CaseResult CheckCase(request::RenderSession& session, const Suite& suite, const SnapshotCase& c,
                     const CaseRenderer& render, Warnings& warnings) {
  const auto start = std::chrono::steady_clock::now();
  CaseResult result;
  CaseRecord& record = result.record;
  record.name = c.name;
  record.index = c.index;
  record.line = c.line;
  record.golden = c.golden;
  record.tolerance = c.tolerance;
  try {
    const image::FrameOutputs outputs{true, c.depth.wanted, c.labels.wanted};
    request::Rendered rendered = render(
        session, c, [&](std::string_view name) { return OptionLocation(suite, c, name); }, warnings, outputs);
    result.robot = rendered.robot;
    result.actual = std::move(rendered.frame.colour);
    Compare(c, result);
    result.colour_status = record.status;
    CompareGray16Goldens(c, rendered.frame, result, *rendered.robot);
  } catch (const Error& e) {
    record.status = CaseStatus::kError;
    record.message = Located(suite, c, e.what());
  }
  record.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace urdfsnap::snapshot
