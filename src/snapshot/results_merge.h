// Joining the results files of a suite's shards into the results of the whole suite, as if it had
// run unsharded (same cases, same verdicts, suite order), each case saying which shard checked it;
// and gathering the shards' report images into one report folder.
#pragma once

#include <string>
#include <vector>

#include "snapshot/results_file.h"

namespace urdfsnap::snapshot {

// A results file and what it holds.
struct ShardFile {
  std::string path;
  RunResults results;
};

struct MergedResults {
  SuiteIdentity suite;
  int shard_count = 1;
  std::vector<CaseRecord> cases;        // in suite order, each with record.shard = "K/N"
  std::vector<std::string> image_dirs;  // per case: the folder of its report images ("" if none)
  std::vector<std::string> sources;     // per case: the results file it came from
};

// Merges the results of every shard of one split. `version` is this urdfsnap's: results of another
// version are refused (renders may differ between versions). Throws urdfsnap::Error naming the
// file(s) for: no files; a file of another suite (digest or case count) or version; files of
// different shard counts; a shard given twice; a missing shard; a case in a shard that does not
// own it, given twice, or cases missing.
MergedResults MergeResults(std::vector<ShardFile> files, const std::string& version);

// Copies the report images of every merged case into `dir` through `outputs` (file names stay
// NAME.expected.png, ...; in place at its Commit). Every image is looked for before any is read.
// Throws urdfsnap::Error naming the results file and key of an image that is not a regular file
// inside its report folder (after symbolic links), or is not there (a partly downloaded artifact).
void CollectReportImages(OutputPlan& outputs, const MergedResults& merged, const std::string& dir);

}  // namespace urdfsnap::snapshot
