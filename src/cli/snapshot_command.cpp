// `urdfsnap snapshot check|update SUITE.yaml`: every case of a suite rendered in one process (one
// GL context, each model loaded once), compared with its golden image, reported; or the goldens
// (re)written after an intended change.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <set>

#include "cli/command.h"
#include "common/error.h"
#include "image/png_writer.h"
#include "gl/gl_context.h"
#include "snapshot/case_check.h"
#include "snapshot/reports.h"

namespace urdfsnap::cli {

namespace {

struct SnapshotOptions {
  std::string suite;
  std::string report_dir, junit;        // check
  std::vector<std::string> case_names;  // update
  bool force = false;                   // update
};

void PrintResult(const char* word, const std::string& name, const std::string& message) {
  std::printf("%-8s %s: %s\n", word, name.c_str(), message.c_str());
  std::fflush(stdout);
}

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
         "  and render's options without the dashes:" + keys + "\n";
}

// Exit status of a run: 2 when a case could not be rendered (bad input), 1 when one differs.
int ExitStatus(const std::vector<snapshot::CaseResult>& results) {
  int status = 0;
  for (const auto& r : results) {
    if (r.status == snapshot::CaseStatus::kError) return 2;
    if (r.status != snapshot::CaseStatus::kPassed) status = 1;
  }
  return status;
}

void Check(const SnapshotOptions& o) {
  const snapshot::Suite suite = snapshot::ReadSuite(o.suite);
  const auto gl_loading = gl::StartLoadingGl();  // overlaps Mesa with the first model
  request::RenderSession session;
  Warnings warnings;
  std::vector<snapshot::CaseResult> results;
  for (const snapshot::SnapshotCase& c : suite.cases) {
    results.push_back(snapshot::CheckCase(session, suite, c, warnings));
    const snapshot::CaseResult& r = results.back();
    PrintResult(snapshot::StatusWord(r.status), c.name, r.message);
  }
  PrintWarnings(warnings);
  if (!o.report_dir.empty()) snapshot::WriteHtmlReport(o.report_dir, suite, results);
  if (!o.junit.empty()) snapshot::WriteJunitReport(o.junit, suite, results);
  std::printf("%s\n", snapshot::Summary(results).c_str());
  if (!o.report_dir.empty()) {
    std::printf("report: %s\n", (std::filesystem::path(o.report_dir) / "index.html").c_str());
  }
  const int status = ExitStatus(results);
  if (status == 1) {
    std::printf("after an intended change: urdfsnap snapshot update %s\n", o.suite.c_str());
  }
  std::fflush(stdout);
  if (status != 0) throw CommandExit{status};
}

// The cases named on the command line (all when none is), in suite order.
std::vector<const snapshot::SnapshotCase*> Selected(const snapshot::Suite& suite,
                                                    const std::vector<std::string>& names) {
  std::set<std::string> wanted(names.begin(), names.end());
  std::vector<const snapshot::SnapshotCase*> selected;
  std::string known;
  for (const snapshot::SnapshotCase& c : suite.cases) {
    known += (known.empty() ? "" : ", ") + c.name;
    if (names.empty() || wanted.erase(c.name)) selected.push_back(&c);
  }
  if (!wanted.empty()) {
    throw Error(suite.path + ": no case named '" + *wanted.begin() + "' (cases: " + known + ")");
  }
  return selected;
}

void Update(const SnapshotOptions& o) {
  const snapshot::Suite suite = snapshot::ReadSuite(o.suite);
  const auto selected = Selected(suite, o.case_names);
  const auto gl_loading = gl::StartLoadingGl();
  request::RenderSession session;
  Warnings warnings;
  std::vector<snapshot::CaseResult> results;
  int written = 0;
  for (const snapshot::SnapshotCase* c : selected) {
    results.push_back(snapshot::CheckCase(session, suite, *c, warnings));
    snapshot::CaseResult& r = results.back();
    if (r.status == snapshot::CaseStatus::kError || (r.status == snapshot::CaseStatus::kPassed && !o.force)) {
      PrintResult(r.status == snapshot::CaseStatus::kError ? "ERROR" : "same", c->name, r.message);
      continue;
    }
    const auto folder = std::filesystem::path(c->golden).parent_path();
    if (!folder.empty()) std::filesystem::create_directories(folder);
    image::WritePng(r.actual, c->golden);
    PrintResult("wrote", c->name, c->golden + " (was " + snapshot::StatusWord(r.status) + ")");
    r.status = snapshot::CaseStatus::kPassed;
    ++written;
  }
  PrintWarnings(warnings);
  std::printf("%d of %zu goldens written; look at each before committing it\n", written, selected.size());
  std::fflush(stdout);
  if (const int status = ExitStatus(results); status != 0) throw CommandExit{status};
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
  check->callback([o] { Check(*o); });
  CLI::App* update = cmd->add_subcommand(
      "update", "(Re)write the golden images of cases that are missing or no longer match");
  update->add_option("SUITE", o->suite, "the suite file (YAML)")->required();
  update->add_option("CASE", o->case_names, "only these cases (default: all)");
  update->add_flag("--force", o->force, "rewrite goldens that still match as well");
  update->callback([o] { Update(*o); });
}

}  // namespace urdfsnap::cli
