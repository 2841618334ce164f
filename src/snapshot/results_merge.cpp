// MergeResults: every check that makes "merged from N shards" mean "the unsharded run", each
// failure a message naming the files; CollectReportImages: the shards' images into one folder.
#include "snapshot/results_merge.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <utility>

#include "common/error.h"
#include "common/file_reading.h"
#include "common/confined_path.h"
#include "shard/shard_assignment.h"

namespace urdfsnap::snapshot {

namespace {

namespace fs = std::filesystem;

std::string Describe(const SuiteIdentity& s) {
  return s.path + " (digest " + s.digest + ", " + std::to_string(s.case_count) + " cases)";
}

// The first file sets the suite and the split; every other must agree.
void CheckSameRun(const ShardFile& first, const ShardFile& file, const std::string& version) {
  const RunResults& r = file.results;
  if (r.urdfsnap_version != version) {
    throw Error(file.path + ": written by urdfsnap " + r.urdfsnap_version + ", this is urdfsnap " +
                version + ": merge with the version that checked the cases");
  }
  const SuiteIdentity& a = first.results.suite;
  if (r.suite.digest != a.digest || r.suite.case_count != a.case_count) {
    throw Error(file.path + ": results of suite " + Describe(r.suite) + ", but " + first.path +
                " has suite " + Describe(a) + ": shards of different suites (or revisions of one) "
                "cannot be merged");
  }
  if (r.shard.count != first.results.shard.count) {
    throw Error(file.path + ": shard " + shard::ShardText(r.shard) + ", but " + first.path + " is shard " +
                shard::ShardText(first.results.shard) + ": all files must come from one split");
  }
}

// Every shard 1..N exactly once.
void CheckShardsComplete(const std::vector<ShardFile>& files) {
  const int count = files.front().results.shard.count;
  std::map<int, const ShardFile*> by_index;
  for (const ShardFile& file : files) {
    const auto [at, added] = by_index.emplace(file.results.shard.index, &file);
    if (!added) {
      throw Error(file.path + ": shard " + shard::ShardText(file.results.shard) + " again (also " +
                  at->second->path + ")");
    }
  }
  std::string given;
  for (const auto& [index, file] : by_index) {
    given += (given.empty() ? "" : ", ") + shard::ShardText({index, count}) + " " + file->path;
  }
  for (int index = 1; index <= count; ++index) {
    if (!by_index.count(index)) {
      throw Error("shard " + shard::ShardText({index, count}) + " is missing: " +
                  std::to_string(by_index.size()) + " of " + std::to_string(count) +
                  " results files given (" + given + ")");
    }
  }
}

}  // namespace

MergedResults MergeResults(std::vector<ShardFile> files, const std::string& version) {
  if (files.empty()) throw Error("no results files to merge");
  for (const ShardFile& file : files) CheckSameRun(files.front(), file, version);
  CheckShardsComplete(files);
  MergedResults merged;
  merged.suite = files.front().results.suite;
  merged.shard_count = files.front().results.shard.count;
  struct Placed {
    CaseRecord record;
    std::string image_dir;
    const std::string* source;
  };
  std::vector<Placed> placed;
  std::map<std::string, const std::string*> owner;  // case name -> results file
  for (ShardFile& file : files) {
    const shard::Shard s = file.results.shard;
    for (CaseRecord& record : file.results.cases) {
      if (!shard::InShard(record.name, s)) {
        throw Error(file.path + ": case '" + record.name + "' does not belong to shard " +
                    shard::ShardText(s) + " (it is shard " +
                    std::to_string(shard::ShardOfName(record.name, s.count)) + "'s): an edited file?");
      }
      if (const auto [at, added] = owner.emplace(record.name, &file.path); !added) {
        throw Error(file.path + ": case '" + record.name + "' again (also in " + *at->second + ")");
      }
      record.shard = shard::ShardText(s);
      placed.push_back({std::move(record), file.results.report_dir, &file.path});
    }
  }
  if (static_cast<int>(placed.size()) != merged.suite.case_count) {
    throw Error(std::to_string(placed.size()) + " cases in the " + std::to_string(files.size()) +
                " results files, but suite " + merged.suite.path + " has " +
                std::to_string(merged.suite.case_count) + ": a results file is incomplete");
  }
  std::sort(placed.begin(), placed.end(),
            [](const Placed& a, const Placed& b) { return a.record.index < b.record.index; });
  merged.cases.reserve(placed.size());
  merged.image_dirs.reserve(placed.size());
  merged.sources.reserve(placed.size());
  for (Placed& p : placed) {
    merged.cases.push_back(std::move(p.record));
    merged.image_dirs.push_back(std::move(p.image_dir));
    merged.sources.push_back(*p.source);
  }
  return merged;
}

void CollectReportImages(OutputPlan& outputs, const MergedResults& merged, const std::string& dir) {
  // every image is looked for before any is copied: a partly downloaded artifact fails the merge
  // before it writes anything
  std::vector<std::pair<fs::path, fs::path>> copies;
  for (std::size_t i = 0; i < merged.cases.size(); ++i) {
    const CaseRecord& r = merged.cases[i];
    for (const auto& [key, file] : ReportImageFiles(r)) {
      const std::string where = merged.sources[i] + ": case '" + r.name + "': " + key;
      if (merged.image_dirs[i].empty()) {
        throw Error(where + ": the file names no report_dir (its run had no --report)");
      }
      const std::string source = ConfineRegularFile(merged.image_dirs[i], file, where);
      copies.emplace_back(source, fs::path(dir) / file);
    }
  }
  for (const auto& [source, target] : copies) {
    std::error_code same_error;
    if (fs::equivalent(source, target, same_error)) continue;  // merged into the shard's own report
    std::string bytes;
    try {
      bytes = ReadFileBounded(source.string(), std::size_t{1} << 30);
    } catch (const FileReadError& e) {
      throw Error(source.string() + ": cannot read the report image: " + e.what());
    }
    outputs.Write(target.string(), bytes);
  }
}

}  // namespace urdfsnap::snapshot
