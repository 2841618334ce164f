// Checking one snapshot case: render it in a shared session, compare it with its golden image
// under the case's tolerance, and keep the images a report shows.
#pragma once

#include <string>

#include "common/warnings.h"
#include "image/image.h"
#include "image/image_diff.h"
#include "request/render_session.h"
#include "snapshot/suite_file.h"

namespace urdfsnap::snapshot {

enum class CaseStatus {
  kPassed,
  kFailed,   // the render differs from the golden beyond the tolerance (or in size)
  kMissing,  // there is no golden image yet
  kError,    // the case could not be rendered or the golden could not be read
};

struct CaseResult {
  const SnapshotCase* snapshot_case = nullptr;
  CaseStatus status = CaseStatus::kError;
  std::string message;   // the figures or the error, one line
  double seconds = 0;    // rendering and comparing
  image::Image expected;  // empty unless the golden was read
  image::Image actual;    // empty when rendering failed
  image::Image diff;      // set for kFailed cases of equal size
};

// Renders `c` and compares it with its golden. Never throws for problems of the case itself:
// they become a kError result whose message names the suite file and line.
CaseResult CheckCase(request::RenderSession& session, const Suite& suite, const SnapshotCase& c,
                     Warnings& warnings);

// "ok", "FAILED", "MISSING" or "ERROR".
const char* StatusWord(CaseStatus status);

}  // namespace urdfsnap::snapshot
