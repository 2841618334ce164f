// Sharded frame sequences and docs pages against the binary: `animate --shard K/N` (and the job
// engines' variables) writes a contiguous range of the frames, colour, depth and labels, numbered
// and drawn exactly as in the unsharded run, every frame in exactly one shard for several N; a
// video is never split; `docs --shard K/N` writes a part of the page's pictures and animations
// whose union over the shards is the unsharded page, byte for byte. Bad shards: exit 2, one line,
// nothing written.
#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "bad_shards.h"
#include "cli_fixture.h"

namespace urdfsnap::cli_test {
namespace {

namespace fs = std::filesystem;

bool Contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// Every file below `folder` by its relative path, with its bytes.
std::map<std::string, std::string> Files(const std::string& folder) {
  std::map<std::string, std::string> files;
  if (!fs::exists(folder)) return files;
  for (const auto& entry : fs::recursive_directory_iterator(folder)) {
    if (entry.is_regular_file()) {
      files[fs::relative(entry.path(), folder).generic_string()] = ReadBytes(entry.path().string());
    }
  }
  return files;
}

// The files of several shards' folders together; a file two shards both wrote counts once when
// `shared` holds its name (the page's text, a label sequence's names) and must then be the same.
std::map<std::string, std::string> Union(const std::vector<std::string>& folders,
                                         const std::set<std::string>& shared) {
  std::map<std::string, std::string> all;
  for (const std::string& folder : folders) {
    for (const auto& [name, bytes] : Files(folder)) {
      const auto [it, inserted] = all.emplace(name, bytes);
      if (inserted) continue;
      EXPECT_TRUE(shared.count(name)) << name << " written by two shards (again in " << folder << ")";
      EXPECT_EQ(it->second, bytes) << name << " differs between shards";
    }
  }
  return all;
}

// How a shard is given: --shard K/N, or one job engine's variables for worker K of N.
using ShardGiving = std::function<std::string(int k, int n, std::string& flag)>;

const ShardGiving kFlag = [](int k, int n, std::string& flag) {
  flag = " --shard " + std::to_string(k) + "/" + std::to_string(n);
  return std::string();
};
const ShardGiving kGitLab = [](int k, int n, std::string&) {
  return "CI_NODE_INDEX=" + std::to_string(k) + " CI_NODE_TOTAL=" + std::to_string(n);
};
// sbatch --array=0-(2N-2):2: task ids 0, 2, 4, ...
const ShardGiving kSlurm = [](int k, int n, std::string&) {
  return "SLURM_ARRAY_TASK_ID=" + std::to_string(2 * (k - 1)) + " SLURM_ARRAY_TASK_MIN=0 SLURM_ARRAY_TASK_STEP=2 " +
         "SLURM_ARRAY_TASK_COUNT=" + std::to_string(n);
};
// a Kubernetes Indexed Job: 0-based index, the count from URDFSNAP_SHARD_COUNT
const ShardGiving kKubernetes = [](int k, int n, std::string&) {
  return "JOB_COMPLETION_INDEX=" + std::to_string(k - 1) + " URDFSNAP_SHARD_COUNT=" + std::to_string(n);
};

// The unsharded run into "whole", then shards of it.
class SequenceShardTest : public CliTest {
 protected:
  void SetUp() override {
    CliTest::SetUp();
    URDFSNAP_REQUIRE_GL();
    const Result whole = RunUrdfsnap(Command("whole"));
    ASSERT_EQ(whole.status, 0) << whole.output;
    whole_ = Files(Path("whole"));
  }

  // The command writing into the folder `out` of the test's folder, or into OUT when it is "OUT".
  virtual std::string Command(const std::string& out) const = 0;

  // Runs Command("OUT") with OUT replaced by each shard's folder, for shards 1..n given by
  // `giving`; expects every run to succeed and say which shard it took. Returns the folders.
  std::vector<std::string> RunShards(int n, const ShardGiving& giving, const std::string& tag) {
    const std::string command = Command("OUT");
    std::vector<std::string> folders;
    for (int k = 1; k <= n; ++k) {
      folders.push_back(Path(tag + "_" + std::to_string(k)));
      std::string flag;
      const std::string environment = giving(k, n, flag);
      std::string arguments = command;
      for (std::size_t at; (at = arguments.find("OUT")) != std::string::npos;) arguments.replace(at, 3, folders.back());
      const Result r = RunUrdfsnap(arguments + flag, environment);
      EXPECT_EQ(r.status, 0) << tag << " " << k << "/" << n << ": " << r.output;
      EXPECT_TRUE(Contains(r.output, "urdfsnap: shard " + std::to_string(k) + "/" + std::to_string(n) + " from "))
          << r.output;
    }
    return folders;
  }

  // Each of `cases` exits 2 with its one error line and writes nothing.
  void ExpectRefused(const std::vector<BadShard>& cases) {
    for (const BadShard& c : cases) {
      const Result r = RunUrdfsnap(Command("bad") + " " + c.arguments, c.environment);
      EXPECT_EQ(r.status, 2) << c.arguments << c.environment << r.output;
      EXPECT_EQ(r.output, "urdfsnap: error: " + c.message + "\n");
      EXPECT_FALSE(fs::exists(Path("bad"))) << c.arguments << c.environment;
    }
  }

  std::map<std::string, std::string> whole_;
};

// --- animate ---------------------------------------------------------------------------------

// mrm waving for 4 s at 3 frames/s (13 frames), the camera fitted over every frame and turning
// once around: a shard that fitted or turned over its own frames only would draw other pictures.
class AnimateShardTest : public SequenceShardTest {
 protected:
  void SetUp() override {
    SequenceShardTest::SetUp();
    if (IsSkipped() || HasFatalFailure()) return;
    ASSERT_EQ(whole_.size(), 3u * kFrames + 1);  // colour, depth, labels per frame, labels.json
  }

  std::string Command(const std::string& out) const override {
    const std::string folder = out == "OUT" ? out : Path(out);
    return "animate " + kMrm + " --trajectory " + (kSource / "examples/trajectories/mrm_wave.csv").string() +
           " --fps 3 --fit --turntable --size 96x72 -q -o " + folder + "/%02d.png --depth " + folder +
           "/depth_%02d.npy --labels " + folder + "/labels_%02d.png";
  }

  // Shards 1..n; their files together are the whole run's, each frame's files written by one shard.
  void ExpectShardsMakeTheWhole(int n, const ShardGiving& giving, const std::string& tag) {
    const auto folders = RunShards(n, giving, tag);
    EXPECT_EQ(Union(folders, {"labels.json"}), whole_) << tag << ", " << n << " shards";
    // contiguous: each shard's colour frames are a run of numbers following the previous shard's
    int next = 0;
    for (const std::string& folder : folders) {
      for (const auto& [name, bytes] : Files(folder)) {
        if (name.size() != 6) continue;  // "07.png"
        char expected[16];
        std::snprintf(expected, sizeof expected, "%02d.png", next);
        EXPECT_EQ(name, expected) << folder;
        ++next;
      }
    }
    EXPECT_EQ(next, kFrames) << tag;
  }

  static constexpr int kFrames = 13;
};

TEST_F(AnimateShardTest, ShardsOfAFrameSequenceAreTheWholeRunsFramesForSeveralCounts) {
  for (int n : {1, 2, 3, 5, 13, 16}) ExpectShardsMakeTheWhole(n, kFlag, "flag" + std::to_string(n));
}

TEST_F(AnimateShardTest, ShardsFromEachJobEnginesVariables) {
  ExpectShardsMakeTheWhole(3, kGitLab, "gitlab");
  ExpectShardsMakeTheWhole(4, kSlurm, "slurm");
  ExpectShardsMakeTheWhole(2, kKubernetes, "kubernetes");
}

TEST_F(AnimateShardTest, TheShardLineSaysWhichFramesAndWhence) {
  Result r = RunUrdfsnap(Command("a"), "CI_NODE_INDEX=2 CI_NODE_TOTAL=3");
  EXPECT_EQ(r.output, "urdfsnap: shard 2/3 from GitLab CI_NODE_INDEX=2 CI_NODE_TOTAL=3: 4 of 13 frames "
                      "(frames 4 to 7)\n");
  // more shards than frames: this one has none, and writes only the label names
  r = RunUrdfsnap(Command("b") + " --shard 1/16");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output, "urdfsnap: shard 1/16 from --shard: 0 of 13 frames (no frames: fewer frames than shards)\n");
  EXPECT_EQ(Files(Path("b")).size(), 1u);
}

TEST_F(AnimateShardTest, FlagWinsAndNoShardIgnoresTheEnvironment) {
  const std::string environment = "CI_NODE_INDEX=2 CI_NODE_TOTAL=3";
  Result r = RunUrdfsnap(Command("flag") + " --shard 1/13", environment);
  EXPECT_TRUE(Contains(r.output, "urdfsnap: shard 1/13 from --shard: 1 of 13 frames (frames 0 to 0)")) << r.output;
  EXPECT_EQ(Files(Path("flag")).size(), 4u);
  r = RunUrdfsnap(Command("all") + " --no-shard", environment);
  EXPECT_EQ(r.output, "");
  EXPECT_EQ(Files(Path("all")), whole_);
}

TEST_F(AnimateShardTest, BadShardsAreOneErrorAndWriteNothing) {
  std::vector<BadShard> cases = kBadShards;
  cases.push_back({"--shard 1/2 --print-frame 3", "",
                   "--shard: --print-frame prints one frame's options and renders nothing to split"});
  ExpectRefused(cases);
}

TEST_F(AnimateShardTest, AVideoIsNeverSplit) {
  const std::string video = "animate " + kMrm + " --turntable --duration 1 --fps 4 --size 96x72 -q -o ";
  for (const char* name : {"turn.mp4", "turn.webm", "turn.gif", "turn.webp"}) {
    const Result r = RunUrdfsnap(video + Path(name) + " --shard 2/3");
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_EQ(r.output.find('\n'), r.output.size() - 1) << r.output;
    EXPECT_TRUE(Contains(r.output, "urdfsnap: error: --shard '2/3': " + Path(name) + " is one ")) << r.output;
    EXPECT_TRUE(Contains(r.output, " file of every frame; only a frame sequence (such as -o frames/%05d.png) "
                                   "is split over workers\n"))
        << r.output;
    EXPECT_FALSE(fs::exists(Path(name)));
  }
  // the environment's shard may be meant for the job's other commands: the video is made whole
  const Result r = RunUrdfsnap(video + Path("turn.gif"), "CI_NODE_INDEX=2 CI_NODE_TOTAL=3");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output, "urdfsnap: not sharded: " + Path("turn.gif") + " is one GIF file of every frame; only a "
                      "frame sequence (such as -o frames/%05d.png) is split over workers; shard 2/3 from "
                      "GitLab CI_NODE_INDEX=2 CI_NODE_TOTAL=3 is set aside, all of it is done here\n");
  ASSERT_EQ(RunUrdfsnap(video + Path("whole.gif")).status, 0);
  EXPECT_EQ(ReadBytes(Path("turn.gif")), ReadBytes(Path("whole.gif")));
  EXPECT_FALSE(ReadBytes(Path("whole.gif")).empty());
}

// --- docs --------------------------------------------------------------------------------------

// mrm's page at a small size: 23 pictures and animations.
class DocsShardTest : public SequenceShardTest {
 protected:
  void SetUp() override {
    SequenceShardTest::SetUp();
    if (IsSkipped() || HasFatalFailure()) return;
    ASSERT_GT(whole_.size(), 10u);
  }

  std::string Command(const std::string& out) const override {
    return "docs " + kMrm + " --size 96x72 -q -o " + (out == "OUT" ? out : Path(out));
  }

  void ExpectShardsMakeThePage(int n, const ShardGiving& giving, const std::string& tag) {
    const auto folders = RunShards(n, giving, tag);
    EXPECT_EQ(Union(folders, {"README.md", "index.html"}), whole_) << tag << ", " << n << " shards";
    for (const std::string& folder : folders) {
      EXPECT_TRUE(fs::exists(folder + "/index.html")) << folder;  // each a page folder, replaceable by -o
    }
  }
};

TEST_F(DocsShardTest, ShardsFoldersTogetherAreTheUnshardedPage) {
  for (int n : {1, 2, 3, 5}) ExpectShardsMakeThePage(n, kFlag, "flag" + std::to_string(n));
  ExpectShardsMakeThePage(3, kGitLab, "gitlab");
  ExpectShardsMakeThePage(2, kSlurm, "slurm");
  ExpectShardsMakeThePage(4, kKubernetes, "kubernetes");
}

TEST_F(DocsShardTest, TheShardLineCountsFilesAndImages) {
  const Result r = RunUrdfsnap(Command("a") + " --shard 1/1");
  EXPECT_TRUE(Contains(r.output, "urdfsnap: shard 1/1 from --shard: ")) << r.output;
  EXPECT_TRUE(Contains(r.output, " pictures and animations (")) << r.output;
  EXPECT_TRUE(Contains(r.output, " images, and the page's text)\n")) << r.output;
  EXPECT_EQ(Files(Path("a")), whole_);
}

TEST_F(DocsShardTest, CheckComparesTheWholePage) {
  // the union of the shards' folders passes --check; --check itself takes no shard
  const auto folders = RunShards(3, kFlag, "s");
  for (const std::string& folder : folders) fs::copy(folder, Path("union"), fs::copy_options::recursive |
                                                                               fs::copy_options::overwrite_existing);
  const std::string check = "docs " + kMrm + " --size 96x72 -q --check " + Path("union");
  Result r = RunUrdfsnap(check, "CI_NODE_INDEX=1 CI_NODE_TOTAL=3");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output, "urdfsnap: not sharded: docs --check compares the whole page with a fresh one; shard 1/3 "
                      "from GitLab CI_NODE_INDEX=1 CI_NODE_TOTAL=3 is set aside, all of it is done here\n" +
                          Path("union") + ": up to date\n");
  r = RunUrdfsnap(check + " --shard 1/3");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_EQ(r.output, "urdfsnap: error: --shard '1/3': docs --check compares the whole page with a fresh one\n");
  // one shard's folder alone is not the page
  r = RunUrdfsnap("docs " + kMrm + " --size 96x72 -q --check " + folders[0]);
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_TRUE(Contains(r.output, ": missing from the committed page")) << r.output;
}

TEST_F(DocsShardTest, BadShardsAreOneErrorAndWriteNothing) { ExpectRefused(kBadShards); }

}  // namespace
}  // namespace urdfsnap::cli_test
