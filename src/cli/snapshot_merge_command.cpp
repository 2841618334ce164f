// `urdfsnap snapshot merge RESULTS.json... [--report DIR] [--junit FILE] [--results FILE]`: the
// results files of a suite's shards (from `snapshot check --results`) joined into one HTML report
// (with the shards' report images), one JUnit file and, if asked, one results file, as if the suite
// had been checked in one run; the exit status is the one that run would have had.
#include <cstdio>
#include <filesystem>
#include <memory>

#include "cli/command.h"
#include "common/version.h"
#include "snapshot/reports.h"
#include "snapshot/results_merge.h"
#include "snapshot/run_outputs.h"

namespace urdfsnap::cli {

namespace {

struct MergeOptions {
  std::vector<std::string> files;
  std::string report_dir, junit, results;
};

void WriteMergedResults(OutputPlan& outputs, const MergeOptions& o, snapshot::MergedResults& merged) {
  snapshot::RunResults results;
  results.suite = merged.suite;
  results.urdfsnap_version = Version();
  results.shard_source = "merged from " + std::to_string(merged.shard_count) + " shards";
  results.report_dir = o.report_dir;
  results.cases = std::move(merged.cases);
  // without a merged report the images stay in the shards' folders, which this file cannot name
  if (o.report_dir.empty()) {
    for (snapshot::CaseRecord& r : results.cases) r.images = {};
  }
  snapshot::WriteResults(outputs, o.results, results);
  merged.cases = std::move(results.cases);
}

void Merge(const MergeOptions& o) {
  std::vector<snapshot::ShardFile> files;
  for (const std::string& path : o.files) files.push_back({path, snapshot::ReadResults(path)});
  snapshot::MergedResults merged = snapshot::MergeResults(std::move(files), Version());
  // the merged files may overwrite neither each other nor a results file; all written, or none
  OutputPlan outputs;
  for (const std::string& path : o.files) outputs.AddInput(path, "the results file");
  std::vector<std::string> names;
  for (const snapshot::CaseRecord& r : merged.cases) names.push_back(r.name);
  snapshot::PlanReports(outputs, {o.report_dir, o.junit, o.results}, names);
  outputs.Prepare();
  if (!o.report_dir.empty()) snapshot::CollectReportImages(outputs, merged, o.report_dir);
  for (const snapshot::CaseRecord& r : merged.cases) {
    if (r.status == snapshot::CaseStatus::kPassed) continue;
    PrintCaseLine(snapshot::StatusWord(r.status), r.name, r.message + " (shard " + r.shard + ")");
  }
  if (!o.report_dir.empty()) {
    snapshot::WriteHtmlReport(outputs, o.report_dir, merged.suite.path, merged.cases);
  }
  if (!o.junit.empty()) snapshot::WriteJunitReport(outputs, o.junit, merged.suite.path, merged.cases);
  if (!o.results.empty()) WriteMergedResults(outputs, o, merged);
  outputs.Commit();
  std::printf("merged %d shards of %s: %s\n", merged.shard_count, merged.suite.path.c_str(),
              snapshot::Summary(merged.cases).c_str());
  if (!o.report_dir.empty()) {
    std::printf("report: %s\n", (std::filesystem::path(o.report_dir) / "index.html").c_str());
  }
  std::fflush(stdout);
  if (const int status = snapshot::ExitStatus(merged.cases); status != 0) throw CommandExit{status};
}

}  // namespace

void AddSnapshotMergeCommand(CLI::App& snapshot) {
  auto o = std::make_shared<MergeOptions>();
  CLI::App* merge = snapshot.add_subcommand(
      "merge", "Merge the results files of a suite's shards (snapshot check --shard K/N --results "
               "FILE) into one report: exit 0 if every case matched, 1 if any differs or has no "
               "golden, 2 if a case could not be rendered or the files do not make up one whole "
               "suite (a shard missing or given twice, another suite or urdfsnap version)");
  merge->add_option("RESULTS", o->files, "the results files, one per shard (any order)")->required();
  merge->add_option("--report", o->report_dir,
                    "write index.html here, with the failing cases' images copied from each "
                    "shard's report folder (found through its results file)");
  merge->add_option("--junit", o->junit, "write JUnit XML for CI systems to this file");
  merge->add_option("--results", o->results, "write the merged results as JSON to this file");
  merge->callback([o] { Merge(*o); });
}

}  // namespace urdfsnap::cli
