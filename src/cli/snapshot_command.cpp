// `urdfsnap snapshot check|update SUITE.yaml`: the cases of a suite (or of one shard of it)
// rendered in one process (one GL context, each model loaded once), compared with their golden
// images and reported; or the goldens (re)written after an intended change. `snapshot merge` is in
// snapshot_merge_command.cpp.
//
// A check keeps one small record per case: each case's report images are written as soon as it
// is checked and then let go, so a suite's memory does not grow with its number of cases.
#include <cstdio>
#include <filesystem>
#include <memory>

#include "cli/bag_still.h"
#include "cli/command.h"
#include "cli/display_options.h"
#include "cli/gl_options.h"
#include "cli/shard_options.h"
#include "common/error.h"
#include "common/number_text.h"
#include "common/version.h"
#include "gl/gl_context.h"
#include "snapshot/case_check.h"
#include "snapshot/case_selection.h"
#include "snapshot/golden_files.h"
#include "snapshot/report_images.h"
#include "snapshot/reports.h"
#include "snapshot/results_file.h"
#include "snapshot/run_outputs.h"

namespace urdfsnap::cli {

namespace {

// A case as `render` draws it: its request, or with a recording moment (bag:, at:, displays:) the
// bag's robot state and display messages at that moment, as `render --bag --at --display` draws it.
request::Rendered RenderCase(request::RenderSession& session, const snapshot::SnapshotCase& c,
                             const request::OptionLabel& label, Warnings& warnings,
                             const image::FrameOutputs& outputs) {
  if (c.moment.bag.empty()) {
    if (!c.moment.at.empty() || !c.moment.displays.empty()) {
      throw Error(label("at") + ": 'at' and 'displays' draw a moment of a recording; give it with 'bag'");
    }
    return session.Render(c.request, label, warnings, outputs);
  }
  BagStillOptions moment;
  moment.bag = c.moment.bag;
  moment.at = c.moment.at;
  DisplayOptions displays;
  displays.displays = c.moment.displays;
  const BagStill still(moment, session, c.request, false, displays, warnings);
  return {still.Draw(session, outputs, warnings), still.prepared().robot};
}

struct SnapshotOptions {
  std::string suite;
  std::string report_dir, junit, results;  // check
  std::vector<std::string> case_names;     // update
  bool force = false;                      // update
  ShardOptions sharding;
  GlOptions gl_options;
};

// The suite format in a few lines, with the option keys taken from the table `render` uses.
std::string SuiteFormatHelp() {
  std::string keys;
  for (const auto& option : request::TextOptions()) keys += std::string(" ") + option.name;
  for (const auto& option : request::FlagOptions()) keys += std::string(" ") + option.name + ":true";
  return "\nSuite file (YAML; paths relative to it):\n"
         "  defaults: {KEY: VALUE, ...}        keys every case starts from\n"
         "  cases:\n"
         "    - name: NAME                     letters, digits, _ - .\n"
         "      golden: FILE.png               default NAME.png\n"
         "      model: ROBOT.urdf|.xacro\n"
         "      args: {NAME: VALUE}            xacro arguments\n"
         "      packages: {PKG: DIR}\n"
         "      joints: {JOINT: VALUE} | FILE  rad or m, or a joint file\n"
         "      max-delta / max-fraction / max-mean: as for urdfsnap diff\n"
         "      depth: true                    also a depth golden NAME.depth.png (16-bit mm);\n"
         "                                     depth-golden: FILE.png, depth-max-delta: MM (default " +
         std::to_string(image::DefaultTolerance(image::Gray16Kind::kDepth).max_delta) + "),\n"
         "                                     depth-max-fraction: F (default " +
         FormatNumber(image::DefaultTolerance(image::Gray16Kind::kDepth).max_fraction) + ")\n"
         "      labels: true                   also a link-label golden NAME.labels.png (+ .json);\n"
         "                                     labels-golden: FILE.png, labels-max-fraction: F (default " +
         FormatNumber(image::DefaultTolerance(image::Gray16Kind::kLabels).max_fraction) + ")\n"
         "  and render's options without the dashes:" + keys + "\n";
}

// The suite's cases this run takes (named ones, of this shard), with the shard line on stderr.
struct Selection {
  snapshot::Suite suite;
  shard::ShardChoice shard;
  std::vector<const snapshot::SnapshotCase*> cases;
};

Selection Select(const SnapshotOptions& o, const std::vector<std::string>& names) {
  Selection s{snapshot::ReadSuite(o.suite), o.sharding.Choose(), {}};
  s.cases = snapshot::SelectCases(s.suite, names, s.shard.shard);
  PrintShardLine(s.shard, s.cases.size(), names.empty() ? s.suite.cases.size() : names.size(),
                 names.empty() ? "cases" : "named cases");
  return s;
}

void WriteOutputs(OutputPlan& outputs, const SnapshotOptions& o, const Selection& s,
                  const std::vector<snapshot::CaseRecord>& records) {
  if (!o.report_dir.empty()) snapshot::WriteHtmlReport(outputs, o.report_dir, s.suite.path, records);
  if (!o.junit.empty()) snapshot::WriteJunitReport(outputs, o.junit, s.suite.path, records);
  if (o.results.empty()) return;
  snapshot::RunResults results;
  results.suite = {s.suite.path, s.suite.digest, static_cast<int>(s.suite.cases.size())};
  results.urdfsnap_version = Version();
  results.shard = s.shard.shard;
  results.shard_source = s.shard.source;
  results.report_dir = o.report_dir;
  results.cases = records;
  snapshot::WriteResults(outputs, o.results, results);
}

void Check(const SnapshotOptions& o) {
  const Selection s = Select(o, {});
  // the reports may overwrite neither each other nor what the cases read; all written, or none
  OutputPlan outputs;
  snapshot::AddSuiteInputs(outputs, s.suite, s.cases, true);
  snapshot::PlanReports(outputs, {o.report_dir, o.junit, o.results}, snapshot::CaseNames(s.cases));
  outputs.Prepare();
  const gl::BackendChoice backend = o.gl_options.Choice();
  const auto gl_loading = gl::StartLoadingGl(backend.backend);  // overlaps Mesa with the first model
  request::RenderSession session(backend);
  Warnings warnings;
  std::vector<snapshot::CaseRecord> records;
  records.reserve(s.cases.size());
  for (const snapshot::SnapshotCase* c : s.cases) {
    snapshot::CaseResult r = snapshot::CheckCase(session, s.suite, *c, RenderCase, warnings);
    if (!o.report_dir.empty()) snapshot::WriteReportImages(outputs, o.report_dir, r);
    PrintCaseLine(snapshot::StatusWord(r.record.status), c->name, r.record.message);
    records.push_back(std::move(r.record));  // the images go with r
  }
  PrintWarnings(warnings);
  WriteOutputs(outputs, o, s, records);
  outputs.Commit();
  std::printf("%s\n", snapshot::Summary(records).c_str());
  if (!o.report_dir.empty()) {
    std::printf("report: %s\n", (std::filesystem::path(o.report_dir) / "index.html").c_str());
  }
  const int status = snapshot::ExitStatus(records);
  if (status == 1) {
    std::printf("after an intended change: urdfsnap snapshot update %s\n", o.suite.c_str());
  }
  std::fflush(stdout);
  if (status != 0) throw CommandExit{status};
}

void Update(const SnapshotOptions& o) {
  const Selection s = Select(o, o.case_names);
  // no golden may be another case's or a file a case reads; those written move into place at the end
  OutputPlan outputs;
  snapshot::AddSuiteInputs(outputs, s.suite, s.cases, false);
  for (const snapshot::SnapshotCase* c : s.cases) snapshot::PlanGoldens(outputs, *c);
  outputs.Prepare();
  const gl::BackendChoice backend = o.gl_options.Choice();
  const auto gl_loading = gl::StartLoadingGl(backend.backend);
  request::RenderSession session(backend);
  Warnings warnings;
  std::vector<snapshot::CaseRecord> records;
  int written = 0;
  for (const snapshot::SnapshotCase* c : s.cases) {
    snapshot::CaseResult r = snapshot::CheckCase(session, s.suite, *c, RenderCase, warnings);
    snapshot::CaseRecord& record = r.record;
    if (record.status == snapshot::CaseStatus::kError ||
        (record.status == snapshot::CaseStatus::kPassed && !o.force)) {
      PrintCaseLine(record.status == snapshot::CaseStatus::kError ? "ERROR" : "same", c->name,
                    record.message);
    } else {
      std::string files;
      for (const std::string& file : snapshot::WriteGoldens(outputs, *c, r, o.force, *r.robot)) {
        files += (files.empty() ? "" : ", ") + file;
        ++written;
      }
      PrintCaseLine("wrote", c->name, files + " (was " + snapshot::StatusWord(record.status) + ")");
      record.status = snapshot::CaseStatus::kPassed;
    }
    records.push_back(std::move(record));
  }
  PrintWarnings(warnings);
  outputs.Commit();
  std::printf("%d goldens of %zu cases written; look at each before committing it\n", written, s.cases.size());
  std::fflush(stdout);
  if (const int status = snapshot::ExitStatus(records); status != 0) throw CommandExit{status};
}

}  // namespace

void AddSnapshotCommand(CLI::App& app) {
  auto o = std::make_shared<SnapshotOptions>();
  CLI::App* cmd = app.add_subcommand(
      "snapshot", "Snapshot tests: render a suite of views and compare them with golden images");
  cmd->require_subcommand(1);
  cmd->footer(SuiteFormatHelp());
  CLI::App* check = cmd->add_subcommand(
      "check", "Render every case and compare it with its golden: exit 0 if all match, 1 if any "
               "differs or has no golden, 2 on bad input");
  check->add_option("SUITE", o->suite, "the suite file (YAML)")->required();
  check->add_option("--report", o->report_dir,
                    "write index.html with expected, actual and diff images of failing cases here");
  check->add_option("--junit", o->junit, "write JUnit XML for CI systems to this file");
  check->add_option("--results", o->results,
                    "write every case's verdict and figures as JSON to this file, for "
                    "`snapshot merge` (format: docs/snapshot-results.md)");
  o->sharding.AddOptions(*check, "cases");
  o->gl_options.AddOptions(*check);
  check->callback([o] { Check(*o); });
  CLI::App* update = cmd->add_subcommand(
      "update", "(Re)write the golden images of cases that are missing or no longer match");
  update->add_option("SUITE", o->suite, "the suite file (YAML)")->required();
  update->add_option("CASE", o->case_names, "only these cases (default: all)");
  update->add_flag("--force", o->force, "rewrite goldens that still match as well");
  o->sharding.AddOptions(*update, "cases");
  o->gl_options.AddOptions(*update);
  update->callback([o] { Update(*o); });
  AddSnapshotMergeCommand(*cmd);
}

}  // namespace urdfsnap::cli
