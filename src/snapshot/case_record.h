// What stays of a checked snapshot case once its images are written: its verdict, figures and the
// names of its report images, a few hundred bytes whatever the image size. A suite run keeps one
// per case (so its memory does not grow with the images of its cases), results files store them
// and `snapshot merge` joins them from several shards.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "image/image_diff.h"

namespace urdfsnap::snapshot {

enum class CaseStatus {
  kPassed,
  kFailed,   // the render differs from the golden beyond the tolerance (or in size)
  kMissing,  // there is no golden image yet
  kError,    // the case could not be rendered or the golden could not be read
};

// The report images of a case: file names inside the report folder, "" for those not written.
struct ReportImages {
  std::string expected, actual, diff;
};

struct CaseRecord {
  std::string name;
  int index = 0;       // position in the suite (0-based): merged shards come back in suite order
  int line = 0;        // of the case in the suite file
  std::string golden;  // path of the golden PNG, as the suite resolved it
  CaseStatus status = CaseStatus::kError;
  std::string message;  // the figures or the error, one line
  double seconds = 0;   // rendering and comparing
  image::DiffTolerance tolerance;
  std::optional<image::DiffStats> figures;  // set when the render was compared with its golden
  ReportImages images;
  std::string shard;  // "K/N" of the shard that checked it, in merged results; "" otherwise
};

// "ok", "FAILED", "MISSING" or "ERROR": the word of the console and the reports.
const char* StatusWord(CaseStatus status);

// "passed", "failed", "missing" or "error": the word of results files.
const char* StatusName(CaseStatus status);

// The status whose StatusName is `name`, or nullopt.
std::optional<CaseStatus> StatusFromName(std::string_view name);

}  // namespace urdfsnap::snapshot
