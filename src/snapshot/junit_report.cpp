// WriteJunitReport, the one-line summary and the exit status: the JUnit XML that CI systems
// (GitLab, Jenkins, GitHub test-report actions) display as a test list.
#include <cstdio>
#include <filesystem>

#include "common/atomic_file.h"
#include "common/markup_text.h"
#include "snapshot/reports.h"

namespace urdfsnap::snapshot {

namespace {

struct Counts {
  int passed = 0, failed = 0, missing = 0, errors = 0;
  double seconds = 0;
};

Counts Count(const std::vector<CaseRecord>& records) {
  Counts counts;
  for (const CaseRecord& r : records) {
    counts.seconds += r.seconds;
    switch (r.status) {
      case CaseStatus::kPassed: ++counts.passed; break;
      case CaseStatus::kFailed: ++counts.failed; break;
      case CaseStatus::kMissing: ++counts.missing; break;
      case CaseStatus::kError: ++counts.errors; break;
    }
  }
  return counts;
}

std::string Seconds(double seconds) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3f", seconds);
  return text;
}

// "\ndepth golden: PATH (FAILED)\nlabels golden: PATH (ok)" for the case's depth and labels goldens.
std::string Gray16Goldens(const CaseRecord& r) {
  std::string text;
  for (const auto& [what, part] : {std::pair{"depth", &r.depth}, std::pair{"labels", &r.labels}}) {
    if (*part) text += std::string("\n") + what + " golden: " + EscapeMarkup((*part)->golden) + " (" + StatusWord((*part)->status) + ")";
  }
  return text;
}

}  // namespace

std::string Summary(const std::vector<CaseRecord>& records) {
  const Counts n = Count(records);
  return std::to_string(records.size()) + " cases: " + std::to_string(n.passed) + " passed, " +
         std::to_string(n.failed) + " failed, " + std::to_string(n.missing) + " missing, " +
         std::to_string(n.errors) + " errors";
}

int ExitStatus(const std::vector<CaseRecord>& records) {
  const Counts n = Count(records);
  if (n.errors > 0) return 2;
  return n.failed + n.missing > 0 ? 1 : 0;
}

void WriteJunitReport(OutputPlan& outputs, const std::string& path, const std::string& suite_path,
                      const std::vector<CaseRecord>& records) {
  const Counts n = Count(records);
  const std::string name = EscapeMarkup(std::filesystem::path(suite_path).stem().string());
  const std::string file = EscapeMarkup(suite_path);
  const std::string counts = "tests=\"" + std::to_string(records.size()) + "\" failures=\"" +
                             std::to_string(n.failed + n.missing) + "\" errors=\"" +
                             std::to_string(n.errors) + "\" time=\"" + Seconds(n.seconds) + "\"";
  // written case by case: the XML of thousands of cases is never held whole in memory
  AtomicFile& xml = outputs.Open(path);
  xml.Write("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites " + counts + ">\n  <testsuite name=\"" +
            name + "\" " + counts + " skipped=\"0\" file=\"" + file + "\">\n");
  for (const CaseRecord& r : records) {
    std::string testcase = "    <testcase classname=\"urdfsnap." + name + "\" name=\"" + EscapeMarkup(r.name) +
                           "\" file=\"" + file + "\" line=\"" + std::to_string(r.line) + "\" time=\"" +
                           Seconds(r.seconds) + "\"";
    if (r.status == CaseStatus::kPassed && r.shard.empty()) {
      xml.Write(testcase + "/>\n");
      continue;
    }
    testcase += ">\n";
    if (!r.shard.empty()) {
      testcase += "      <properties><property name=\"shard\" value=\"" + EscapeMarkup(r.shard) +
                  "\"/></properties>\n";
    }
    if (r.status != CaseStatus::kPassed) {
      const std::string element = r.status == CaseStatus::kError ? "error" : "failure";
      const std::string message = EscapeMarkup(r.message);
      testcase += "      <" + element + " type=\"" + StatusWord(r.status) + "\" message=\"" + message +
                  "\">" + message + "\ngolden: " + EscapeMarkup(r.golden) + Gray16Goldens(r) +
                  (r.shard.empty() ? "" : "\nshard: " + EscapeMarkup(r.shard)) + "</" + element + ">\n";
    }
    xml.Write(testcase + "    </testcase>\n");
  }
  xml.Write("  </testsuite>\n</testsuites>\n");
  xml.Close();
}

}  // namespace urdfsnap::snapshot
