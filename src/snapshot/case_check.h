// Checking one snapshot case: render it in a shared session (colour, and depth and labels when the
// case has those goldens), compare each image with its golden under its tolerance, and hold the
// images a report shows until they are written.
#pragma once

#include <functional>

#include "common/warnings.h"
#include "image/image.h"
#include "request/render_session.h"
#include "snapshot/case_record.h"
#include "snapshot/suite_file.h"

namespace urdfsnap::snapshot {

// A depth or labels image of a case just checked.
struct Gray16Result {
  image::Gray16Image actual;  // the render's, as its golden stores it (millimetres, 1 + link index)
  // viewable pictures for the report (see image::DepthPicture, LabelPicture), set when it did not pass
  image::Image expected_picture, actual_picture, diff_picture;
};

// A case just checked: its record, and its images until the report has them (then dropped, so
// that a suite's memory does not grow with its cases).
struct CaseResult {
  CaseRecord record;
  CaseStatus colour_status = CaseStatus::kError;  // of the colour image alone
  image::Image expected;  // empty unless the golden was read
  image::Image actual;    // empty when rendering failed
  image::Image diff;      // set for kFailed cases of equal size
  Gray16Result depth, labels;  // for cases with those goldens
  std::shared_ptr<const model::Robot> robot;  // the robot rendered; null when rendering failed
};

// How a case is drawn: its request through `session` (labels naming the suite's lines), into the
// images `outputs` asks for. The command supplies it, since a case with a recording moment is drawn
// as `render --bag` draws one.
using CaseRenderer = std::function<request::Rendered(request::RenderSession& session, const SnapshotCase& c,
                                                     const request::OptionLabel& label, Warnings& warnings,
                                                     const image::FrameOutputs& outputs)>;

// Renders `c` through `render` and compares it with its goldens. Never throws for problems of the
// case itself: they become a kError result whose message names the suite file and line.
CaseResult CheckCase(request::RenderSession& session, const Suite& suite, const SnapshotCase& c,
                     const CaseRenderer& render, Warnings& warnings);

}  // namespace urdfsnap::snapshot
