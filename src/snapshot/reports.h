// What a snapshot check or merge leaves for people and CI systems: an HTML report showing the
// images of every case that did not pass, and JUnit XML. Both are written from case records, so a
// merge of several shards' results writes them the same way as a single run.
#pragma once

#include <string>
#include <vector>

#include "common/output_plan.h"
#include "snapshot/case_record.h"

namespace urdfsnap::snapshot {

// Writes `dir`/index.html through `outputs` (see ReportIndexFile; in place at its Commit): a summary table, then per case
// that did not pass its figures, its images (record.images, files already in `dir`: see
// WriteReportImages) side by side and a slider that swipes between expected and actual. The page
// is self-contained (inline CSS and JavaScript, images beside it, nothing from the network). With
// records from several shards (record.shard set) the table has a shard column. Throws
// urdfsnap::Error when the file cannot be written.
void WriteHtmlReport(OutputPlan& outputs, const std::string& dir, const std::string& suite_path,
                     const std::vector<CaseRecord>& records);

// Writes JUnit XML to `path` through `outputs`: one <testsuite> named after the suite file, one
// <testcase> per case, <failure> for failed or missing goldens, <error> for cases that could not
// be rendered; a case from a shard carries a "shard" property.
void WriteJunitReport(OutputPlan& outputs, const std::string& path, const std::string& suite_path,
                      const std::vector<CaseRecord>& records);

// "5 cases: 3 passed, 1 failed, 1 missing, 0 errors".
std::string Summary(const std::vector<CaseRecord>& records);

// The exit status of a check: 2 when a case could not be rendered (bad input), else 1 when a case
// differs or has no golden, else 0.
int ExitStatus(const std::vector<CaseRecord>& records);

}  // namespace urdfsnap::snapshot
