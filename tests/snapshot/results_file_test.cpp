// Results files: every field of a record survives writing and reading, the report folder is kept
// relative to the results file, and a damaged or foreign file (or one whose report folder leads out
// of its folder) is refused naming the field.
#include "snapshot/results_file.h"

#include <filesystem>
#include <functional>
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "common/error.h"
#include "support/temp_folder.h"

namespace urdfsnap::snapshot {
namespace {

namespace fs = std::filesystem;

CaseRecord FailedCase() {
  CaseRecord r;
  r.name = "reach_forward";
  r.index = 7;
  r.line = 23;
  r.golden = "test/snapshots/reach_forward.png";
  r.status = CaseStatus::kFailed;
  r.message = "max delta 96, mean delta 0.41 (limit 0.1)";
  r.seconds = 0.0123;
  r.tolerance = {12, 0.0005, 0.25};
  r.figures = image::DiffStats{96, 0.41, 0.00264, 812, 233, 120, 301, 274};
  r.images = {"reach_forward.expected.png", "reach_forward.actual.png", "reach_forward.diff.png"};
  r.depth = Gray16Record{"test/snapshots/reach_forward.depth.png", CaseStatus::kFailed, "max delta 466 mm", {3, 0.0002},
                         image::Gray16DiffStats{466, 2289, 288, 0.00745, 234, 95, 327, 206},
                         {"reach_forward.depth.expected.png", "reach_forward.depth.actual.png", "reach_forward.depth.diff.png"}};
  r.labels = Gray16Record{"test/snapshots/reach_forward.labels.png", CaseStatus::kMissing, "no labels golden",
                          {0, 0}, std::nullopt, {"", "reach_forward.labels.actual.png", ""}};
  return r;
}

RunResults Sample(const std::string& report_dir) {
  RunResults results;
  results.suite = {"test/snapshots/suite.yaml", "0123456789abcdef", 40};
  results.urdfsnap_version = "0.1.0";
  results.shard = {2, 4};
  results.shard_source = "GitLab CI_NODE_INDEX=2 CI_NODE_TOTAL=4";
  results.report_dir = report_dir;
  results.cases.push_back(FailedCase());
  CaseRecord passed;
  passed.name = "home";
  passed.index = 0;
  passed.status = CaseStatus::kPassed;
  passed.figures = image::DiffStats{};  // identical: no region
  results.cases.push_back(passed);
  CaseRecord error;
  error.name = "broken";
  error.index = 3;
  error.status = CaseStatus::kError;
  error.message = "suite.yaml:9: case 'broken': robot 'arm' has no joint 'x' \xff";  // not UTF-8
  results.cases.push_back(error);
  return results;
}

void ExpectSame(const CaseRecord& a, const CaseRecord& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.index, b.index);
  EXPECT_EQ(a.line, b.line);
  EXPECT_EQ(a.golden, b.golden);
  EXPECT_EQ(a.status, b.status);
  EXPECT_EQ(a.seconds, b.seconds);
  EXPECT_EQ(a.tolerance.max_delta, b.tolerance.max_delta);
  EXPECT_EQ(a.tolerance.max_fraction, b.tolerance.max_fraction);
  EXPECT_EQ(a.tolerance.max_mean, b.tolerance.max_mean);
  ASSERT_EQ(a.figures.has_value(), b.figures.has_value());
  if (a.figures) {
    EXPECT_EQ(a.figures->max_delta, b.figures->max_delta);
    EXPECT_EQ(a.figures->mean_delta, b.figures->mean_delta);
    EXPECT_EQ(a.figures->fraction_over, b.figures->fraction_over);
    EXPECT_EQ(a.figures->pixels_over, b.figures->pixels_over);
    EXPECT_EQ(a.figures->min_x, b.figures->min_x);
    EXPECT_EQ(a.figures->max_y, b.figures->max_y);
  }
  EXPECT_EQ(a.images.expected, b.images.expected);
  EXPECT_EQ(a.images.actual, b.images.actual);
  EXPECT_EQ(a.images.diff, b.images.diff);
  EXPECT_EQ(a.shard, b.shard);
  for (const auto& [x, y] : {std::pair{&a.depth, &b.depth}, std::pair{&a.labels, &b.labels}}) {
    ASSERT_EQ(x->has_value(), y->has_value());
    if (!*x) continue;
    EXPECT_EQ((*x)->golden, (*y)->golden);
    EXPECT_EQ((*x)->status, (*y)->status);
    EXPECT_EQ((*x)->message, (*y)->message);
    EXPECT_EQ((*x)->tolerance.max_delta, (*y)->tolerance.max_delta);
    EXPECT_EQ((*x)->tolerance.max_fraction, (*y)->tolerance.max_fraction);
    ASSERT_EQ((*x)->figures.has_value(), (*y)->figures.has_value());
    if ((*x)->figures) {
      EXPECT_EQ((*x)->figures->max_delta, (*y)->figures->max_delta);
      EXPECT_EQ((*x)->figures->pixels_over, (*y)->figures->pixels_over);
      EXPECT_EQ((*x)->figures->pixels_coverage, (*y)->figures->pixels_coverage);
      EXPECT_EQ((*x)->figures->fraction_over, (*y)->figures->fraction_over);
      EXPECT_EQ((*x)->figures->min_y, (*y)->figures->min_y);
      EXPECT_EQ((*x)->figures->max_x, (*y)->figures->max_x);
    }
    EXPECT_EQ(ReportImageFiles(a), ReportImageFiles(b));
  }
}

// WriteResults through a plan of its own, committed.
void WriteResultsFile(const std::string& path, const RunResults& results) {
  OutputPlan outputs;
  WriteResults(outputs, path, results);
  outputs.Commit();
}

class ResultsFileTest : public ::testing::Test {
 protected:
  std::string Path(const std::string& name) const { return (folder_.path() / name).string(); }
  void Write(const std::string& name, const std::string& text) const {
    std::ofstream(Path(name)) << text;
  }
  test::TempFolder folder_{"results_file"};
};

TEST_F(ResultsFileTest, EveryFieldSurvivesAndTheReportFolderStaysBesideTheFile) {
  fs::create_directories(Path("shard-2"));
  const RunResults written = Sample(Path("shard-2/report"));
  WriteResultsFile(Path("shard-2/results.json"), written);
  // the file names its report folder relative to itself: the pair can be moved as an artifact
  std::ifstream in(Path("shard-2/results.json"));
  const auto json = nlohmann::json::parse(in);
  EXPECT_EQ(json["report_dir"], "report");
  EXPECT_EQ(json["cases"][2]["message"], "suite.yaml:9: case 'broken': robot 'arm' has no joint 'x' \xef\xbf\xbd");
  fs::rename(Path("shard-2"), Path("downloaded"));
  const RunResults read = ReadResults(Path("downloaded/results.json"));
  EXPECT_EQ(read.report_dir, Path("downloaded/report"));
  EXPECT_EQ(read.suite.path, written.suite.path);
  EXPECT_EQ(read.suite.digest, written.suite.digest);
  EXPECT_EQ(read.suite.case_count, 40);
  EXPECT_EQ(read.urdfsnap_version, "0.1.0");
  EXPECT_EQ(read.shard.index, 2);
  EXPECT_EQ(read.shard.count, 4);
  EXPECT_EQ(read.shard_source, written.shard_source);
  ASSERT_EQ(read.cases.size(), 3u);
  ExpectSame(read.cases[0], written.cases[0]);
  ExpectSame(read.cases[1], written.cases[1]);
  EXPECT_EQ(read.cases[1].figures->min_x, -1);  // no region
  EXPECT_EQ(read.cases[2].status, CaseStatus::kError);
  EXPECT_FALSE(read.cases[2].figures.has_value());
  EXPECT_FALSE(read.cases[1].depth.has_value());  // a case without depth and labels goldens
  EXPECT_EQ(ReportImageFiles(read.cases[0]).size(), 7u);
}

TEST_F(ResultsFileTest, WithoutAReportTheFolderIsEmpty) {
  WriteResultsFile(Path("results.json"), Sample(""));
  EXPECT_EQ(ReadResults(Path("results.json")).report_dir, "");
}

TEST_F(ResultsFileTest, DamagedOrForeignFilesNameTheField) {
  WriteResultsFile(Path("good.json"), Sample(Path("report")));
  std::ifstream in(Path("good.json"));
  const nlohmann::json good = nlohmann::json::parse(in);
  struct Case {
    std::function<void(nlohmann::json&)> damage;
    std::string message;
  } cases[] = {
      {[](auto& j) { j.erase("format"); }, "not a urdfsnap results file"},
      {[](auto& j) { j["format_version"] = 2; }, "results format version 2; this urdfsnap reads version 1"},
      {[](auto& j) { j["suite"].erase("digest"); }, "suite.digest: missing"},
      {[](auto& j) { j["shard"]["index"] = 5; }, "shard.index: expected a whole number from 1 to 4, got 5"},
      {[](auto& j) { j["shard"]["count"] = "4"; }, "shard.count: expected a whole number from 1 to 1000000, got \"4\""},
      {[](auto& j) { j["cases"] = 3; }, "cases: expected a list"},
      {[](auto& j) { j["cases"][1]["status"] = "ok"; },
       "cases[1].status: expected passed, failed, missing or error, got 'ok'"},
      {[](auto& j) { j["cases"][0]["figures"]["max_delta"] = 2.5; },
       "cases[0].figures.max_delta: expected a whole number from 0 to 255, got 2.5"},
      {[](auto& j) { j["cases"][0]["name"] = "../escape"; }, "cases[0].name: '../escape' is not a case name"},
      {[](auto& j) { j["cases"][0]["images"]["diff"] = "../../etc/passwd"; },
       "cases[0].images.diff: '../../etc/passwd' is not a file name"},
      {[](auto& j) { j["cases"][2].erase("tolerance"); }, "cases[2].tolerance: missing"},
      {[](auto& j) { j["cases"][0]["depth"]["images"]["diff"] = "/tmp/x.png"; },
       "cases[0].depth.images.diff: '/tmp/x.png' is not a file name"},
      {[](auto& j) { j["cases"][0]["depth"]["status"] = "error"; },
       "cases[0].depth.status: expected passed, failed or missing, got 'error'"},
      {[](auto& j) { j["cases"][0]["depth"]["figures"]["pixels_coverage"] = -3; },
       "cases[0].depth.figures.pixels_coverage: expected a whole number from 0 to 2147483647, got -3"},
      {[](auto& j) { j["cases"][0]["labels"].erase("golden"); }, "cases[0].labels.golden: missing"},
      {[](auto& j) { j["cases"][0]["labels"] = 1; }, "cases[0].labels: expected an object, got 1"},
      // the report folder stays inside the results file's folder, however it is written
      {[](auto& j) { j["report_dir"] = "../../../../../../etc"; }, "report_dir: '../../../../../../etc' leads outside"},
      {[](auto& j) { j["report_dir"] = "/etc"; }, "report_dir: '/etc' leads outside"},
      {[](auto& j) { j["report_dir"] = "report/../.."; }, "report_dir: 'report/../..' leads outside"},
      {[](auto& j) { j["report_dir"] = "escape"; }, "report_dir: 'escape' leads outside"},  // a link
  };
  fs::create_directory_symlink("/etc", Path("escape"));
  for (const Case& c : cases) {
    nlohmann::json damaged = good;
    c.damage(damaged);
    Write("damaged.json", damaged.dump());
    try {
      ReadResults(Path("damaged.json"));
      ADD_FAILURE() << "accepted: " << c.message;
    } catch (const Error& e) {
      EXPECT_EQ(std::string(e.what()).rfind(Path("damaged.json") + ": " + c.message, 0), 0u) << e.what();
    }
  }
}

}  // namespace
}  // namespace urdfsnap::snapshot
