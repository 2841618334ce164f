// The files of a report folder: index.html (reports.h), and the images of each case that did not
// pass, written as soon as the case is checked: NAME.expected.png, NAME.actual.png and
// NAME.diff.png (those it has), and for a depth or labels image that did not pass its viewable
// pictures NAME.depth.expected.png, ..., NAME.labels.diff.png.
#pragma once

#include <string>
#include <vector>

#include "common/output_plan.h"
#include "snapshot/case_check.h"

namespace urdfsnap::snapshot {

// The report page in `dir`: DIR/index.html.
std::string ReportIndexFile(const std::string& dir);

// Every image file name a case named `name` can have in a report folder (nine).
std::vector<std::string> ReportImageNames(const std::string& name);

// Adds the report in `dir` of cases named `names` to `outputs`: its page and every image name
// each case can have (role `role`, "--report").
void PlanReport(OutputPlan& outputs, const std::string& dir, const std::vector<std::string>& names,
                const std::string& role);

// Writes the images of `result` into `dir` through `outputs` (in place at its Commit) unless the
// case passed, records their file names in result.record.images and frees the images. Throws
// urdfsnap::Error naming a file that cannot be written.
void WriteReportImages(OutputPlan& outputs, const std::string& dir, CaseResult& result);

}  // namespace urdfsnap::snapshot
