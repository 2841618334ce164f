// The words for a case's status, both ways.
#include "snapshot/case_record.h"

namespace urdfsnap::snapshot {

namespace {

constexpr CaseStatus kStatuses[] = {CaseStatus::kPassed, CaseStatus::kFailed, CaseStatus::kMissing,
                                    CaseStatus::kError};

}  // namespace

std::vector<std::pair<std::string, std::string>> ReportImageFiles(const CaseRecord& record) {
  std::vector<std::pair<std::string, const ReportImages*>> sets{{"images", &record.images}};
  if (record.depth) sets.emplace_back("depth.images", &record.depth->images);
  if (record.labels) sets.emplace_back("labels.images", &record.labels->images);
  std::vector<std::pair<std::string, std::string>> files;
  for (const auto& [key, images] : sets) {
    for (const auto& [kind, file] : {std::pair{".expected", &images->expected}, std::pair{".actual", &images->actual},
                                     std::pair{".diff", &images->diff}}) {
      if (!file->empty()) files.emplace_back(key + kind, *file);
    }
  }
  return files;
}

CaseStatus CombinedStatus(std::initializer_list<CaseStatus> parts) {
  CaseStatus status = CaseStatus::kPassed;
  for (const CaseStatus part : parts) {
    if (part == CaseStatus::kFailed) return part;
    if (part == CaseStatus::kMissing) status = part;
  }
  return status;
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

const char* StatusName(CaseStatus status) {
  switch (status) {
    case CaseStatus::kPassed: return "passed";
    case CaseStatus::kFailed: return "failed";
    case CaseStatus::kMissing: return "missing";
    case CaseStatus::kError: return "error";
  }
  return "error";
}

std::optional<CaseStatus> StatusFromName(std::string_view name) {
  for (const CaseStatus status : kStatuses) {
    if (name == StatusName(status)) return status;
  }
  return std::nullopt;
}

}  // namespace urdfsnap::snapshot
