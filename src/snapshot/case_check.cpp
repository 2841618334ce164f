// CheckCase: one render, one golden read, one comparison; failures become results, not exceptions.
#include "snapshot/case_check.h"

#include <chrono>
#include <filesystem>

#include "common/error.h"
#include "image/png_reader.h"

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

}  // namespace

CaseResult CheckCase(request::RenderSession& session, const Suite& suite, const SnapshotCase& c,
                     Warnings& warnings) {
  const auto start = std::chrono::steady_clock::now();
  CaseResult result;
  CaseRecord& record = result.record;
  record.name = c.name;
  record.index = c.index;
  record.line = c.line;
  record.golden = c.golden;
  record.tolerance = c.tolerance;
  try {
    result.actual = session.Render(
        c.request, [&](std::string_view name) { return OptionLocation(suite, c, name); }, warnings).colour;
    Compare(c, result);
  } catch (const Error& e) {
    record.status = CaseStatus::kError;
    record.message = Located(suite, c, e.what());
  }
  record.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace urdfsnap::snapshot
