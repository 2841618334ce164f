// WriteJunitReport and the one-line summary: the JUnit XML that CI systems (GitLab, Jenkins,
// GitHub test-report actions) display as a test list.
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "common/atomic_file.h"
#include "snapshot/markup_text.h"
#include "snapshot/reports.h"

namespace urdfsnap::snapshot {

namespace {

struct Counts {
  int passed = 0, failed = 0, missing = 0, errors = 0;
  double seconds = 0;
};

Counts Count(const std::vector<CaseResult>& results) {
  Counts counts;
  for (const CaseResult& r : results) {
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

}  // namespace

std::string Summary(const std::vector<CaseResult>& results) {
  const Counts n = Count(results);
  return std::to_string(results.size()) + " cases: " + std::to_string(n.passed) + " passed, " +
         std::to_string(n.failed) + " failed, " + std::to_string(n.missing) + " missing, " +
         std::to_string(n.errors) + " errors";
}

void WriteJunitReport(const std::string& path, const Suite& suite,
                      const std::vector<CaseResult>& results) {
  const Counts n = Count(results);
  const std::string name = EscapeMarkup(std::filesystem::path(suite.path).stem().string());
  const std::string counts = "tests=\"" + std::to_string(results.size()) + "\" failures=\"" +
                             std::to_string(n.failed + n.missing) + "\" errors=\"" +
                             std::to_string(n.errors) + "\" time=\"" + Seconds(n.seconds) + "\"";
  std::ostringstream xml;
  xml << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites " << counts << ">\n"
      << "  <testsuite name=\"" << name << "\" " << counts << " skipped=\"0\" file=\""
      << EscapeMarkup(suite.path) << "\">\n";
  for (const CaseResult& r : results) {
    const SnapshotCase& c = *r.snapshot_case;
    xml << "    <testcase classname=\"urdfsnap." << name << "\" name=\"" << EscapeMarkup(c.name)
        << "\" file=\"" << EscapeMarkup(suite.path) << "\" line=\"" << c.line << "\" time=\""
        << Seconds(r.seconds) << "\"";
    if (r.status == CaseStatus::kPassed) {
      xml << "/>\n";
      continue;
    }
    const char* element = r.status == CaseStatus::kError ? "error" : "failure";
    const std::string message = EscapeMarkup(r.message);
    xml << ">\n      <" << element << " type=\"" << StatusWord(r.status) << "\" message=\""
        << message << "\">" << message << "\ngolden: " << EscapeMarkup(c.golden) << "</"
        << element << ">\n    </testcase>\n";
  }
  xml << "  </testsuite>\n</testsuites>\n";
  WriteFileAtomically(path, xml.str());
}

}  // namespace urdfsnap::snapshot
