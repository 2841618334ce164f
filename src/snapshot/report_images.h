// The images of a case that did not pass, written into the report folder as soon as the case is
// checked: NAME.expected.png, NAME.actual.png and NAME.diff.png (those it has), and for a depth or
// labels image that did not pass its viewable pictures NAME.depth.expected.png, ...,
// NAME.labels.diff.png.
#pragma once

#include <string>

#include "snapshot/case_check.h"

namespace urdfsnap::snapshot {

// Writes the images of `result` into `dir` (which must exist) unless the case passed, each
// atomically, records their file names in result.record.images and frees the images. Throws
// urdfsnap::Error naming a file that cannot be written.
void WriteReportImages(const std::string& dir, CaseResult& result);

}  // namespace urdfsnap::snapshot
