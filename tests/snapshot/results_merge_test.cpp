// MergeResults on records alone: suite order back, each case labelled with its shard, and the
// checks that keep a merge equal to an unsharded run (ownership, duplicates, completeness);
// CollectReportImages copying from each shard's folder.
#include "snapshot/results_merge.h"

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "common/error.h"
#include "shard/shard_assignment.h"
#include "support/temp_folder.h"

namespace urdfsnap::snapshot {
namespace {

namespace fs = std::filesystem;

// The results of shard `shard` of a suite of `names`, as a check would write them.
ShardFile ShardOf(const std::vector<std::string>& names, shard::Shard shard, const std::string& dir = "") {
  ShardFile file{"shard" + std::to_string(shard.index) + ".json", {}};
  file.results.suite = {"suite.yaml", "feedfacefeedface", static_cast<int>(names.size())};
  file.results.urdfsnap_version = "1.2.3";
  file.results.shard = shard;
  file.results.report_dir = dir;
  for (int i = 0; i < static_cast<int>(names.size()); ++i) {
    if (!shard::InShard(names[i], shard)) continue;
    CaseRecord r;
    r.name = names[i];
    r.index = i;
    r.status = i % 4 == 0 ? CaseStatus::kFailed : CaseStatus::kPassed;
    if (r.status == CaseStatus::kFailed) {
      r.images.actual = r.name + ".actual.png";
      r.depth = Gray16Record{r.name + ".depth.png", CaseStatus::kFailed, "", {}, std::nullopt, {}};
      r.depth->images.diff = r.name + ".depth.diff.png";
    }
    file.results.cases.push_back(r);
  }
  return file;
}

std::vector<std::string> Names(int count) {
  std::vector<std::string> names;
  for (int i = 0; i < count; ++i) names.push_back("case_" + std::to_string(i));
  return names;
}

std::string MergeError(std::vector<ShardFile> files) {
  try {
    MergeResults(std::move(files), "1.2.3");
  } catch (const Error& e) {
    return e.what();
  }
  return "(merged)";
}

TEST(ResultsMerge, SuiteOrderAndShardLabels) {
  const auto names = Names(30);
  std::vector<ShardFile> files;
  for (int k = 4; k >= 1; --k) files.push_back(ShardOf(names, {k, 4}));
  const MergedResults merged = MergeResults(std::move(files), "1.2.3");
  ASSERT_EQ(merged.cases.size(), 30u);
  EXPECT_EQ(merged.shard_count, 4);
  for (int i = 0; i < 30; ++i) {
    EXPECT_EQ(merged.cases[i].name, names[i]);
    EXPECT_EQ(merged.cases[i].shard, std::to_string(shard::ShardOfName(names[i], 4)) + "/4");
  }
}

TEST(ResultsMerge, RefusesWhatIsNotOneWholeRun) {
  const auto names = Names(30);
  auto all = [&] {
    std::vector<ShardFile> files;
    for (int k = 1; k <= 3; ++k) files.push_back(ShardOf(names, {k, 3}));
    return files;
  };
  EXPECT_EQ(MergeError({}), "no results files to merge");
  auto files = all();
  files[1].results.cases.pop_back();
  EXPECT_EQ(MergeError(files), "29 cases in the 3 results files, but suite suite.yaml has 30: a results file is incomplete");
  files = all();
  files[0].results.cases.push_back(files[1].results.cases.front());
  EXPECT_EQ(MergeError(files).rfind("shard1.json: case '" + files[1].results.cases.front().name +
                                    "' does not belong to shard 1/3 (it is shard 2's)", 0), 0u);
  files = all();
  files[2].results.cases.push_back(files[2].results.cases.front());
  EXPECT_EQ(MergeError(files), "shard3.json: case '" + files[2].results.cases.front().name +
                                   "' again (also in shard3.json)");
  files = all();
  files[2].results.suite.case_count = 31;
  EXPECT_EQ(MergeError(files).rfind("shard3.json: results of suite suite.yaml (digest feedfacefeedface, 31 cases), but "
                                    "shard1.json has suite suite.yaml (digest feedfacefeedface, 30 cases)", 0), 0u);
  files = all();
  files.erase(files.begin());
  EXPECT_EQ(MergeError(files), "shard 1/3 is missing: 2 of 3 results files given (2/3 shard2.json, 3/3 shard3.json)");
}

TEST(ResultsMerge, ReportImagesComeFromEachShardsFolder) {
  test::TempFolder folder("results_merge");
  const auto names = Names(12);
  std::vector<ShardFile> files;
  for (int k = 1; k <= 2; ++k) {
    const fs::path dir = folder.path() / ("shard" + std::to_string(k));
    fs::create_directories(dir);
    files.push_back(ShardOf(names, {k, 2}, dir.string()));
    for (const CaseRecord& r : files.back().results.cases) {
      for (const auto& [key, file] : ReportImageFiles(r)) std::ofstream(dir / file) << "png of " << file;
    }
  }
  const MergedResults merged = MergeResults(std::move(files), "1.2.3");
  const fs::path out = folder.path() / "merged";
  const auto collect = [&](const fs::path& dir) {
    fs::create_directories(dir);
    OutputPlan outputs;
    CollectReportImages(outputs, merged, dir.string());
    outputs.Commit();
  };
  collect(out);
  int copied = 0;
  for (const CaseRecord& r : merged.cases) {
    for (const auto& [key, file] : ReportImageFiles(r)) {
      std::ifstream in(out / file);
      std::string text;
      std::getline(in, text);
      EXPECT_EQ(text, "png of " + file);
      ++copied;
    }
  }
  EXPECT_EQ(copied, 6);  // case_0, case_4, case_8: colour and depth
  // merging into a shard's own folder leaves its images in place
  collect(folder.path() / "shard1");
  // a depth image that did not come along fails the merge, naming it
  for (const CaseRecord& r : merged.cases) {
    if (!r.depth) continue;
    fs::remove(folder.path() / ("shard" + r.shard.substr(0, 1)) / r.depth->images.diff);
    try {
      collect(folder.path() / "again");
      ADD_FAILURE() << "merged without " << r.depth->images.diff;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(r.depth->images.diff), std::string::npos) << e.what();
    }
    break;
  }
}

TEST(ResultsMerge, AnImageThatLeadsOutOfItsReportFolderIsRefusedBeforeAnythingIsWritten) {
  test::TempFolder folder("results_merge");
  const fs::path dir = folder.path() / "shard";
  fs::create_directories(dir);
  std::vector<ShardFile> files{ShardOf(Names(3), {1, 1}, dir.string())};
  std::string linked;
  for (const CaseRecord& r : files.back().results.cases) {
    for (const auto& [key, file] : ReportImageFiles(r)) {
      if (linked.empty()) {
        fs::create_symlink("/etc/passwd", dir / file);  // an artifact with a link in it
        linked = r.name + "': " + key + ": '" + file + "' leads outside";
      } else {
        std::ofstream(dir / file) << "png";
      }
    }
  }
  ASSERT_FALSE(linked.empty());
  const MergedResults merged = MergeResults(std::move(files), "1.2.3");
  const fs::path out = folder.path() / "merged";
  fs::create_directories(out);
  try {
    OutputPlan outputs;
    CollectReportImages(outputs, merged, out.string());
    outputs.Commit();
    ADD_FAILURE() << "copied through a link";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(linked), std::string::npos) << e.what();
  }
  EXPECT_TRUE(fs::is_empty(out));
}

}  // namespace
}  // namespace urdfsnap::snapshot
