// PlanReports and AddSuiteInputs: each file under the words a message names it by.
#include "snapshot/run_outputs.h"

#include <filesystem>

#include "common/confined_path.h"
#include "common/error.h"
#include "image/depth_label_files.h"
#include "request/request_inputs.h"
#include "snapshot/report_images.h"

namespace urdfsnap::snapshot {

void PlanReports(OutputPlan& outputs, const ReportOutputs& reports, const std::vector<std::string>& names) {
  if (!reports.report_dir.empty()) {
    if (!reports.results.empty()) {
      const std::string folder = std::filesystem::path(reports.results).parent_path().string();
      if (ResolveInside(folder, std::filesystem::absolute(reports.report_dir).string()).empty()) {
        throw Error("--report '" + reports.report_dir + "': must be inside the folder of --results '" +
                    reports.results + "' (`snapshot merge` takes report images from there only)");
      }
    }
    PlanReport(outputs, reports.report_dir, names, "--report");
  }
  if (!reports.junit.empty()) outputs.AddFile(reports.junit, "--junit");
  if (!reports.results.empty()) outputs.AddFile(reports.results, "--results");
}

void AddSuiteInputs(OutputPlan& outputs, const Suite& suite, const std::vector<const SnapshotCase*>& cases,
                    bool goldens) {
  outputs.AddInput(suite.path, "the suite");
  for (const SnapshotCase* c : cases) {
    const std::string where = suite.path + ":" + std::to_string(c->line) + ": case '" + c->name + "': ";
    request::AddRequestInputs(outputs, c->request, where);
    if (!c->moment.bag.empty()) outputs.AddInput(c->moment.bag, where + "bag");
    if (!goldens) continue;
    outputs.AddInput(c->golden, where + "the golden");
    if (c->depth.wanted) outputs.AddInput(c->depth.golden, where + "the depth golden");
    if (c->labels.wanted) {
      outputs.AddInput(c->labels.golden, where + "the labels golden");
      outputs.AddInput(image::LabelNamesFile(c->labels.golden), where + "the link names");
    }
  }
}

std::vector<std::string> CaseNames(const std::vector<const SnapshotCase*>& cases) {
  std::vector<std::string> names;
  names.reserve(cases.size());
  for (const SnapshotCase* c : cases) names.push_back(c->name);
  return names;
}

}  // namespace urdfsnap::snapshot
