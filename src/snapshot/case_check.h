// Checking one snapshot case: render it in a shared session, compare it with its golden image
// under the case's tolerance, and hold the images a report shows until they are written.
#pragma once

#include "common/warnings.h"
#include "image/image.h"
#include "request/render_session.h"
#include "snapshot/case_record.h"
#include "snapshot/suite_file.h"

namespace urdfsnap::snapshot {

// A case just checked: its record, and its images until the report has them (then dropped, so
// that a suite's memory does not grow with its cases).
struct CaseResult {
  CaseRecord record;
  image::Image expected;  // empty unless the golden was read
  image::Image actual;    // empty when rendering failed
  image::Image diff;      // set for kFailed cases of equal size
};

// Renders `c` and compares it with its golden. Never throws for problems of the case itself:
// they become a kError result whose message names the suite file and line.
CaseResult CheckCase(request::RenderSession& session, const Suite& suite, const SnapshotCase& c,
                     Warnings& warnings);

}  // namespace urdfsnap::snapshot
