// Results files: every case's verdict and figures from one `snapshot check` run (one shard, or the
// whole suite as shard 1/1), written by `--results FILE.json` and read by `snapshot merge`. The
// format is documented in docs/snapshot-results.md (format version kResultsFormatVersion).
#pragma once

#include <string>
#include <vector>

#include "common/output_plan.h"
#include "shard/shard_spec.h"
#include "snapshot/case_record.h"

namespace urdfsnap::snapshot {

inline constexpr int kResultsFormatVersion = 1;

// Which suite results belong to: shards merge only when all three agree.
struct SuiteIdentity {
  std::string path;    // as given to `snapshot check`
  std::string digest;  // Suite::digest, the hash of the suite file's bytes
  int case_count = 0;  // cases in the whole suite, not only in this shard
};

struct RunResults {
  SuiteIdentity suite;
  std::string urdfsnap_version;  // of the urdfsnap that checked the cases
  shard::Shard shard;
  std::string shard_source;  // where the shard came from ("--shard", "GitLab ..."); "" if unsharded
  // The folder holding the cases' report images ("" when no report was written): a path usable
  // from the working directory. In the file it is relative to the results file's folder, so a
  // results file and its report can be moved together (CI artifacts); it must lie inside that
  // folder (ReadResults refuses a file whose report_dir leads out of it).
  std::string report_dir;
  std::vector<CaseRecord> cases;  // in suite order
};

// Writes `results` to `path` as JSON through `outputs` (in place at its Commit). Throws
// urdfsnap::Error naming the path when it cannot be written.
void WriteResults(OutputPlan& outputs, const std::string& path, const RunResults& results);

// Reads a results file. Throws urdfsnap::Error "PATH: ..." for a file that cannot be read, is not
// JSON, is not a urdfsnap results file or has another format version, has a missing or mistyped
// field (named by its place, e.g. "cases[3].status"), or a report_dir outside the file's folder
// (after symbolic links: "PATH: report_dir: '../..' leads outside ..."). report_dir is returned
// resolved (absolute, no links).
RunResults ReadResults(const std::string& path);

}  // namespace urdfsnap::snapshot
