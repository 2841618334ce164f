// The output plan of a snapshot run (common/output_plan.h): the files `check` and `merge` write
// (the HTML report with every image name its cases can have, the JUnit file, the results file)
// and those `update` writes (the goldens), against the files the suite's cases read, so that no
// output of a run overwrites another or an input, and a run that fails leaves no file behind.
#pragma once

#include <string>
#include <vector>

#include "common/output_plan.h"
#include "snapshot/suite_file.h"

namespace urdfsnap::snapshot {

// The report files asked for ("" when not asked), by option.
struct ReportOutputs {
  std::string report_dir;  // --report
  std::string junit;       // --junit
  std::string results;     // --results
};

// Adds the files of `reports` for cases named `names` to `outputs`. Throws urdfsnap::Error when
// the report folder is not inside the results file's folder (a results file names its report
// folder relative to itself, and `merge` takes nothing from outside that folder).
void PlanReports(OutputPlan& outputs, const ReportOutputs& reports, const std::vector<std::string>& names);

// Adds the suite file and every file `cases` read (models, joint and .rviz files, and with
// `goldens` their golden images) to `outputs` as inputs.
void AddSuiteInputs(OutputPlan& outputs, const Suite& suite, const std::vector<const SnapshotCase*>& cases,
                    bool goldens);

// The names of `cases`.
std::vector<std::string> CaseNames(const std::vector<const SnapshotCase*>& cases);

}  // namespace urdfsnap::snapshot
