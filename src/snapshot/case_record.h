// What stays of a checked snapshot case once its images are written: its verdict, figures and the
// names of its report images, a few hundred bytes whatever the image size. A suite run keeps one
// per case (so its memory does not grow with the images of its cases), results files store them
// and `snapshot merge` joins them from several shards.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>
#include <initializer_list>
#include <utility>

#include "image/gray16_diff.h"
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

// The comparison of a case's depth or labels golden (suite keys depth: / labels:).
struct Gray16Record {
  std::string golden;                              // its path, as the suite resolved it
  CaseStatus status = CaseStatus::kError;          // kPassed, kFailed or kMissing
  std::string message;                             // its figures, or what is missing
  image::Gray16Tolerance tolerance;
  std::optional<image::Gray16DiffStats> figures;   // set when compared with a golden of its size
  ReportImages images;                             // viewable pictures: false-colour depth, coloured labels
};

struct CaseRecord {
  std::string name;
  int index = 0;       // position in the suite (0-based): merged shards come back in suite order
  int line = 0;        // of the case in the suite file
  std::string golden;  // path of the golden PNG, as the suite resolved it
  CaseStatus status = CaseStatus::kError;  // of the whole case: colour, depth and labels
  std::string message;  // the figures or the error, one line (depth's and labels' after the colour's)
  double seconds = 0;   // rendering and comparing
  image::DiffTolerance tolerance;
  std::optional<image::DiffStats> figures;  // set when the render was compared with its golden
  ReportImages images;
  std::optional<Gray16Record> depth, labels;  // for cases with depth or labels goldens
  std::string camera;  // "camera moved: ..." when the stored camera is not the one the case gives now
  std::string shard;  // "K/N" of the shard that checked it, in merged results; "" otherwise
};

// Every report image file name of `record` (colour, depth and labels), those written only, each
// with its key in a results file's case ("images.actual", "depth.images.diff").
std::vector<std::pair<std::string, std::string>> ReportImageFiles(const CaseRecord& record);

// The status of a case whose parts (colour, depth, labels) have these statuses: failed if one
// failed, else missing if one is missing, else passed (kError does not come from parts).
CaseStatus CombinedStatus(std::initializer_list<CaseStatus> parts);

// "ok", "FAILED", "MISSING" or "ERROR": the word of the console and the reports.
const char* StatusWord(CaseStatus status);

// "passed", "failed", "missing" or "error": the word of results files.
const char* StatusName(CaseStatus status);

// The status whose StatusName is `name`, or nullopt.
std::optional<CaseStatus> StatusFromName(std::string_view name);

}  // namespace urdfsnap::snapshot
