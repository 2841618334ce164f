// Sharded suites end to end: a suite of passing, failing, missing and broken cases checked whole,
// then as N shards (through --shard and through GitLab's, Slurm's and Kubernetes' variables) and
// merged: every case exactly once, and the merged results, JUnit and exit status equal to the
// unsharded run's. Then every way a shard or a merge can be given bad input: exit 2, one error
// line, nothing written.
#include <filesystem>
#include <functional>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "bad_shards.h"
#include "cli_fixture.h"

namespace urdfsnap::cli_test {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

bool Contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// Lines of `text` that contain `part`.
int CountLines(const std::string& text, const std::string& part) {
  int count = 0;
  for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++count;
  return count;
}

Json ReadJson(const std::string& path) { return Json::parse(ReadBytes(path)); }

// A case of a results file without what may differ between runs: its time and shard.
Json Comparable(Json c) {
  c.erase("seconds");
  c.erase("shard");
  return c;
}

// The JUnit XML without times and the shard notes a merge adds.
std::string ComparableJunit(const std::string& xml) {
  std::string out = std::regex_replace(xml, std::regex(" time=\"[0-9.]+\""), "");
  out = std::regex_replace(out, std::regex("\n *<properties><property name=\"shard\" value=\"[0-9/]+\"/></properties>"), "");
  out = std::regex_replace(out, std::regex("\nshard: [0-9/]+<"), "<");
  return std::regex_replace(out, std::regex(">\n *</testcase>"), "/>");
}

// 15 cases of mrm at 160x120: 12 that match their goldens, one whose golden is another view
// (FAILED), one without golden (MISSING), one with an unknown joint (ERROR).
class ShardedSuiteTest : public CliTest {
 protected:
  void SetUp() override {
    CliTest::SetUp();
    std::string yaml = "defaults:\n  model: " + kMrm + "\n  size: 160x120\ncases:\n";
    for (int i = 0; i < 12; ++i) {
      const std::string name = "view_" + std::to_string(i);
      names_.push_back(name);
      yaml += "  - name: " + name + "\n    yaw: " + std::to_string(0.3 * i) +
              "\n    joints: {link_01__link_02: " + std::to_string(0.1 * i) + "}\n";
    }
    yaml += "  - name: drifted\n    joints: {link_02__link_03: 1.0}\n"
            "  - name: new_view\n    pitch: 1.2\n"
            "  - name: broken\n    joints: {nope: 1}\n";
    names_.insert(names_.end(), {"drifted", "new_view", "broken"});
    suite_ = Write("suite.yaml", yaml);
    const Result update = RunUrdfsnap("snapshot update " + suite_);
    ASSERT_EQ(update.status, 2) << update.output;  // the broken case
    fs::remove(Path("new_view.png"));
    fs::copy_file(Path("view_0.png"), Path("drifted.png"), fs::copy_options::overwrite_existing);
    whole_ = RunUrdfsnap("snapshot check " + suite_ + " --results " + Path("whole.json") +
                         " --junit " + Path("whole.xml") + " --report " + Path("whole_report"));
    ASSERT_EQ(whole_.status, 2) << whole_.output;
  }

  // Runs shard K/N for K = 1..N with `environment(K)` or --shard, into folder `tag`; returns the
  // results files.
  std::vector<std::string> RunShards(int count, const std::string& tag,
                                     const std::function<std::string(int)>& environment = {}) {
    std::vector<std::string> files;
    std::multiset<std::string> seen;
    for (int k = 1; k <= count; ++k) {
      const std::string dir = Path(tag + "_" + std::to_string(k));
      fs::create_directories(dir);
      const std::string flag = environment ? "" : " --shard " + std::to_string(k) + "/" + std::to_string(count);
      const Result r = RunUrdfsnap("snapshot check " + suite_ + flag + " --results " + dir +
                                       "/results.json --report " + dir + "/report",
                                   environment ? environment(k) : "");
      EXPECT_NE(r.status, -1) << r.output;
      EXPECT_TRUE(Contains(r.output, "urdfsnap: shard " + std::to_string(k) + "/" + std::to_string(count) + " from "))
          << r.output;
      files.push_back(dir + "/results.json");
      const Json results = ReadJson(files.back());
      for (const Json& c : results["cases"]) seen.insert(c["name"].get<std::string>());
    }
    // every case in exactly one shard
    EXPECT_EQ(seen, std::multiset<std::string>(names_.begin(), names_.end())) << tag;
    return files;
  }

  // Merges `files`, and expects the same cases, verdicts, figures, JUnit and status as the whole run.
  void ExpectMergeEqualsWhole(const std::vector<std::string>& files, const std::string& tag) {
    std::string arguments = "snapshot merge";
    for (auto it = files.rbegin(); it != files.rend(); ++it) arguments += " " + *it;  // any order
    const Result r = RunUrdfsnap(arguments + " --results " + Path(tag + ".json") + " --junit " +
                                 Path(tag + ".xml") + " --report " + Path(tag + "_report"));
    EXPECT_EQ(r.status, whole_.status) << r.output;
    EXPECT_TRUE(Contains(r.output, "merged " + std::to_string(files.size()) + " shards of " + suite_ +
                                       ": 15 cases: 12 passed, 1 failed, 1 missing, 1 errors"))
        << r.output;
    EXPECT_TRUE(Contains(r.output, "FAILED   drifted: ")) << r.output;
    EXPECT_TRUE(Contains(r.output, "(shard ")) << r.output;
    const Json whole = ReadJson(Path("whole.json")), merged = ReadJson(Path(tag + ".json"));
    ASSERT_EQ(merged["cases"].size(), whole["cases"].size()) << tag;
    for (std::size_t i = 0; i < whole["cases"].size(); ++i) {
      EXPECT_EQ(Comparable(merged["cases"][i]), Comparable(whole["cases"][i])) << tag;
      EXPECT_TRUE(merged["cases"][i].contains("shard")) << tag;
    }
    EXPECT_EQ(merged["suite"], whole["suite"]);
    EXPECT_EQ(ComparableJunit(ReadBytes(Path(tag + ".xml"))), ComparableJunit(ReadBytes(Path("whole.xml"))))
        << tag;
    // the merged report has each failing case's images, copied from the shard that checked it
    const std::string html = ReadBytes(Path(tag + "_report/index.html"));
    EXPECT_TRUE(Contains(html, "<th>shard</th>")) << tag;
    for (const char* file : {"drifted.expected.png", "drifted.actual.png", "drifted.diff.png",
                             "new_view.actual.png"}) {
      EXPECT_EQ(ReadBytes(Path(tag + "_report/") + file), ReadBytes(Path("whole_report/") + file))
          << tag << " " << file;
      EXPECT_TRUE(Contains(html, std::string("src=\"") + file + "\"")) << tag << " " << file;
    }
  }

  std::string suite_;
  std::vector<std::string> names_;
  Result whole_;
};

TEST_F(ShardedSuiteTest, MergedShardsEqualTheUnshardedRunForSeveralCounts) {
  for (int count : {1, 2, 3, 5}) {
    const std::string tag = "flag" + std::to_string(count);
    ExpectMergeEqualsWhole(RunShards(count, tag), tag);
  }
}

TEST_F(ShardedSuiteTest, ShardsFromEachJobEnginesVariables) {
  ExpectMergeEqualsWhole(RunShards(3, "gitlab", [](int k) {
    return "CI_NODE_INDEX=" + std::to_string(k) + " CI_NODE_TOTAL=3";
  }), "gitlab");
  // sbatch --array=1-4: tasks 1..4
  ExpectMergeEqualsWhole(RunShards(4, "slurm", [](int k) {
    return "SLURM_ARRAY_TASK_ID=" + std::to_string(k) + " SLURM_ARRAY_TASK_MIN=1 SLURM_ARRAY_TASK_COUNT=4";
  }), "slurm");
  // an Indexed Job with completions: 2; the index is 0-based
  ExpectMergeEqualsWhole(RunShards(2, "kubernetes", [](int k) {
    return "JOB_COMPLETION_INDEX=" + std::to_string(k - 1) + " URDFSNAP_SHARD_COUNT=2";
  }), "kubernetes");
  const Result gitlab = RunUrdfsnap("snapshot check " + suite_, "CI_NODE_INDEX=2 CI_NODE_TOTAL=3");
  EXPECT_TRUE(Contains(gitlab.output, "urdfsnap: shard 2/3 from GitLab CI_NODE_INDEX=2 CI_NODE_TOTAL=3: "))
      << gitlab.output;
  EXPECT_TRUE(Contains(gitlab.output, " of 15 cases\n")) << gitlab.output;
}

TEST_F(ShardedSuiteTest, FlagWinsAndNoShardIgnoresTheEnvironment) {
  const std::string environment = "CI_NODE_INDEX=2 CI_NODE_TOTAL=3";
  Result r = RunUrdfsnap("snapshot check " + suite_ + " --shard 1/2 --results " + Path("a.json"), environment);
  EXPECT_TRUE(Contains(r.output, "urdfsnap: shard 1/2 from --shard: ")) << r.output;
  EXPECT_EQ(ReadJson(Path("a.json"))["shard"], (Json{{"index", 1}, {"count", 2}, {"source", "--shard"}}));
  r = RunUrdfsnap("snapshot check " + suite_ + " --no-shard --results " + Path("b.json"), environment);
  EXPECT_FALSE(Contains(r.output, "urdfsnap: shard")) << r.output;
  EXPECT_EQ(ReadJson(Path("b.json"))["cases"].size(), 15u);
  r = RunUrdfsnap("snapshot check " + suite_ + " --no-shard --shard 1/2");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_TRUE(Contains(r.output, "urdfsnap: error: ")) << r.output;
}

TEST_F(ShardedSuiteTest, UpdateWritesOnlyItsShardsGoldens) {
  for (const std::string& name : names_) fs::remove(Path(name + ".png"));
  std::set<std::string> written;
  for (int k = 1; k <= 2; ++k) {
    const Result r = RunUrdfsnap("snapshot update " + suite_ + " --shard " + std::to_string(k) + "/2");
    EXPECT_TRUE(Contains(r.output, "urdfsnap: shard " + std::to_string(k) + "/2 from --shard: ")) << r.output;
    std::set<std::string> now;
    for (const std::string& name : names_) {
      if (fs::exists(Path(name + ".png"))) now.insert(name);
    }
    for (const std::string& name : written) EXPECT_TRUE(now.count(name)) << name;
    EXPECT_GT(now.size(), written.size()) << "shard " << k << " wrote nothing";
    if (k == 1) {
      EXPECT_LT(now.size(), 14u) << "shard 1 wrote every golden";
    }
    written = now;
  }
  written.insert("broken");  // never renders, so never gets a golden
  EXPECT_EQ(written, std::set<std::string>(names_.begin(), names_.end()));
  // a named case outside the shard is simply not this shard's
  const Result r = RunUrdfsnap("snapshot update " + suite_ + " view_0 view_1 view_2 --shard 1/2 --force");
  EXPECT_TRUE(Contains(r.output, "of 3 named cases")) << r.output;
}

TEST_F(ShardedSuiteTest, BadShardsAreOneErrorAndWriteNothing) {
  for (const BadShard& c : kBadShards) {
    const Result r = RunUrdfsnap("snapshot check " + suite_ + " " + c.arguments + " --results " +
                                     Path("bad.json") + " --junit " + Path("bad.xml"),
                                 c.environment);
    EXPECT_EQ(r.status, 2) << c.arguments << c.environment << r.output;
    EXPECT_EQ(r.output, "urdfsnap: error: " + c.message + "\n");
    EXPECT_FALSE(fs::exists(Path("bad.json")));
    EXPECT_FALSE(fs::exists(Path("bad.xml")));
    EXPECT_EQ(RunUrdfsnap("snapshot update " + suite_ + " " + c.arguments, c.environment).status, 2);
  }
}

TEST_F(ShardedSuiteTest, MergeRefusesResultsThatAreNotOneWholeSuite) {
  const auto files = RunShards(3, "s");
  const auto other_split = RunShards(2, "t");
  Write("other.yaml", "cases:\n  - name: view_0\n    model: " + kMrm + "\n    size: 160x120\n");
  ASSERT_NE(RunUrdfsnap("snapshot check " + Path("other.yaml") + " --shard 2/3 --results " +
                        Path("other.json")).status, -1);
  Json old_version = ReadJson(files[1]);
  old_version["urdfsnap_version"] = "0.0.9";
  Write("old.json", old_version.dump());
  Write("junit.json", "{\"testsuites\": []}");
  Write("cut.json", ReadBytes(files[0]).substr(0, 300));
  struct Case {
    std::string files, message;
  } cases[] = {
      {files[0] + " " + files[2], "shard 2/3 is missing: 2 of 3 results files given (1/3 " + files[0]},
      {files[0] + " " + files[1] + " " + files[1] + " " + files[2], files[1] + ": shard 2/3 again (also " + files[1] + ")"},
      {files[0] + " " + other_split[1] + " " + files[2], other_split[1] + ": shard 2/2, but " + files[0] +
                                                             " is shard 1/3: all files must come from one split"},
      {files[0] + " " + Path("other.json") + " " + files[2],
       Path("other.json") + ": results of suite " + Path("other.yaml") + " (digest "},
      {files[0] + " " + Path("old.json") + " " + files[2],
       Path("old.json") + ": written by urdfsnap 0.0.9, this is urdfsnap "},
      {files[0] + " " + Path("junit.json"), Path("junit.json") + ": not a urdfsnap results file"},
      {Path("cut.json"), Path("cut.json") + ":1: bad JSON: "},
      {Path("none.json"), Path("none.json") + ": cannot read the results file: No such file or directory"},
  };
  for (const Case& c : cases) {
    const Result r = RunUrdfsnap("snapshot merge " + c.files + " --report " + Path("merged") +
                                 " --junit " + Path("merged.xml"));
    EXPECT_EQ(r.status, 2) << c.files << "\n" << r.output;
    EXPECT_EQ(r.output.rfind("urdfsnap: error: " + c.message, 0), 0u) << c.message << "\n" << r.output;
    EXPECT_EQ(CountLines(r.output, "\n"), 1) << r.output;
    EXPECT_FALSE(fs::exists(Path("merged"))) << c.files;
    EXPECT_FALSE(fs::exists(Path("merged.xml"))) << c.files;
  }
  // a shard's report folder that did not come along with its results file
  fs::remove(Path("s_2/report/drifted.diff.png"));
  fs::remove(Path("s_1/report/drifted.diff.png"));
  fs::remove(Path("s_3/report/drifted.diff.png"));
  const Result r = RunUrdfsnap("snapshot merge " + files[0] + " " + files[1] + " " + files[2] +
                               " --report " + Path("merged"));
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_TRUE(Contains(r.output, "/results.json: case 'drifted': images.diff: 'drifted.diff.png' is not a regular "
                                 "file (it is not there)")) << r.output;
  EXPECT_FALSE(fs::exists(Path("merged"))) << "images copied before the missing one was found";
}

}  // namespace
}  // namespace urdfsnap::cli_test
