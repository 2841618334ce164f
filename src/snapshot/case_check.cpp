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
  if (!std::filesystem::exists(c.golden)) {
    result.status = CaseStatus::kMissing;
    result.message = "no golden image " + c.golden;
    return;
  }
  result.expected = image::ReadPng(c.golden);
  if (result.expected.width != result.actual.width || result.expected.height != result.actual.height) {
    result.status = CaseStatus::kFailed;
    result.message = "size differs: golden " + c.golden + " is " + image::SizeText(result.expected) +
                     ", the render is " + image::SizeText(result.actual);
    return;
  }
  const int delta = c.tolerance.max_delta;
  const image::DiffStats stats = image::CompareImages(result.expected, result.actual, delta);
  result.message = image::DescribeDiff(stats, c.tolerance);
  if (image::WithinTolerance(stats, c.tolerance)) {
    result.status = CaseStatus::kPassed;
    return;
  }
  result.status = CaseStatus::kFailed;
  result.diff = image::MakeDiffImage(result.expected, result.actual, delta);
}

}  // namespace

CaseResult CheckCase(request::RenderSession& session, const Suite& suite, const SnapshotCase& c,
                     Warnings& warnings) {
  const auto start = std::chrono::steady_clock::now();
  CaseResult result;
  result.snapshot_case = &c;
  try {
    result.actual = session.Render(
        c.request, [&](std::string_view name) { return OptionLocation(suite, c, name); }, warnings).colour;
    Compare(c, result);
  } catch (const Error& e) {
    result.status = CaseStatus::kError;
    result.message = Located(suite, c, e.what());
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

const char* StatusWord(CaseStatus status) {
  switch (status) {
    case CaseStatus::kPassed: return "ok";
    case CaseStatus::kFailed: return "FAILED";
    case CaseStatus::kMissing: return "MISSING";
    case CaseStatus::kError: return "ERROR";
  }
  return "ERROR";
}

}  // namespace urdfsnap::snapshot
