// What a snapshot check leaves for people and CI systems: an HTML report with the images of every
// case that did not pass, and JUnit XML.
#pragma once

#include <string>
#include <vector>

#include "snapshot/case_check.h"
#include "snapshot/suite_file.h"

namespace urdfsnap::snapshot {

// Writes into `dir` (created if needed) NAME.expected.png, NAME.actual.png and NAME.diff.png for
// every case that did not pass (those it has) and index.html: a summary table, then per case the
// three images side by side and a slider that swipes between expected and actual. The page is
// self-contained (inline CSS and JavaScript, images beside it, nothing from the network).
// Every file is written atomically. Throws urdfsnap::Error when a file cannot be written.
void WriteHtmlReport(const std::string& dir, const Suite& suite, const std::vector<CaseResult>& results);

// Writes JUnit XML to `path` atomically: one <testsuite> named after the suite file, one
// <testcase> per case, <failure> for failed or missing goldens, <error> for cases that could not
// be rendered.
void WriteJunitReport(const std::string& path, const Suite& suite,
                      const std::vector<CaseResult>& results);

// "5 cases: 3 passed, 1 failed, 1 missing, 0 errors".
std::string Summary(const std::vector<CaseResult>& results);

}  // namespace urdfsnap::snapshot
