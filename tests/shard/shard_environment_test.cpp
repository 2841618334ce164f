// The job engines' variables turned into K/N, as a table: GitLab (1-based), Slurm arrays (offset
// by their minimum, with a step), Kubernetes Indexed Jobs (0-based, count from
// URDFSNAP_SHARD_COUNT); the flag winning and --no-shard ignoring them; every bad value an error
// that names the variable.
#include "shard/shard_environment.h"

#include <map>
#include <string>

#include <gtest/gtest.h>

#include "common/error.h"

namespace urdfsnap::shard {
namespace {

using Environment = std::map<std::string, std::string>;

EnvironmentLookup Lookup(const Environment& environment) {
  return [&environment](const char* name) -> const char* {
    const auto found = environment.find(name);
    return found == environment.end() ? nullptr : found->second.c_str();
  };
}

struct Case {
  Environment environment;
  std::string shard;    // "K/N", "" for not sharded
  std::string source;   // or the error's beginning
  bool error = false;
};

void Check(const Case& c) {
  SCOPED_TRACE(c.source);
  try {
    const std::optional<ShardChoice> choice = ShardFromEnvironment(Lookup(c.environment));
    ASSERT_FALSE(c.error) << "no error";
    if (c.shard.empty()) {
      EXPECT_FALSE(choice.has_value());
      return;
    }
    ASSERT_TRUE(choice.has_value());
    EXPECT_EQ(ShardText(choice->shard), c.shard);
    EXPECT_EQ(choice->source, c.source);
  } catch (const Error& e) {
    ASSERT_TRUE(c.error) << e.what();
    EXPECT_EQ(std::string(e.what()).rfind(c.source, 0), 0u) << e.what();
  }
}

TEST(ShardEnvironment, NothingSetMeansNotSharded) {
  Check({{}, "", ""});
  Check({{{"CI_NODE_TOTAL", "1"}}, "", ""});  // every GitLab job has it; only parallel: sets the index
  Check({{{"SLURM_JOB_ID", "42"}}, "", ""});  // a Slurm job that is no array
}

TEST(ShardEnvironment, GitLab) {
  Check({{{"CI_NODE_INDEX", "2"}, {"CI_NODE_TOTAL", "4"}}, "2/4", "GitLab CI_NODE_INDEX=2 CI_NODE_TOTAL=4"});
  Check({{{"CI_NODE_INDEX", "4"}, {"CI_NODE_TOTAL", "4"}}, "4/4", "GitLab CI_NODE_INDEX=4 CI_NODE_TOTAL=4"});
  Check({{{"CI_NODE_INDEX", "5"}, {"CI_NODE_TOTAL", "4"}}, "",
         "GitLab CI_NODE_INDEX=5 CI_NODE_TOTAL=4: the shard index must be from 1 to 4, got 5", true});
  Check({{{"CI_NODE_INDEX", "0"}, {"CI_NODE_TOTAL", "4"}}, "",
         "GitLab CI_NODE_INDEX=0 CI_NODE_TOTAL=4: the shard index must be from 1 to 4, got 0", true});
  Check({{{"CI_NODE_INDEX", "two"}, {"CI_NODE_TOTAL", "4"}}, "",
         "environment variable CI_NODE_INDEX=two: expected a whole number", true});
  Check({{{"CI_NODE_INDEX", "2"}}, "",
         "GitLab parallel job: CI_NODE_INDEX=2 is set but CI_NODE_TOTAL is not set", true});
}

TEST(ShardEnvironment, SlurmArrayOffsetByItsMinimum) {
  const Environment base = {{"SLURM_ARRAY_TASK_MIN", "5"}, {"SLURM_ARRAY_TASK_COUNT", "3"}};
  auto with = [&](Environment extra) {
    extra.insert(base.begin(), base.end());
    return extra;
  };
  Check({with({{"SLURM_ARRAY_TASK_ID", "5"}}), "1/3",
         "Slurm SLURM_ARRAY_TASK_ID=5 SLURM_ARRAY_TASK_MIN=5 SLURM_ARRAY_TASK_COUNT=3"});
  Check({with({{"SLURM_ARRAY_TASK_ID", "7"}}), "3/3",
         "Slurm SLURM_ARRAY_TASK_ID=7 SLURM_ARRAY_TASK_MIN=5 SLURM_ARRAY_TASK_COUNT=3"});
  Check({with({{"SLURM_ARRAY_TASK_ID", "8"}}), "",
         "Slurm SLURM_ARRAY_TASK_ID=8 SLURM_ARRAY_TASK_MIN=5 SLURM_ARRAY_TASK_COUNT=3: the shard "
         "index must be from 1 to 3, got 4", true});
  Check({with({{"SLURM_ARRAY_TASK_ID", "4"}}), "", "Slurm SLURM_ARRAY_TASK_ID=4", true});
  Check({{{"SLURM_ARRAY_TASK_ID", "3"}}, "",
         "Slurm job array: SLURM_ARRAY_TASK_ID=3 is set but SLURM_ARRAY_TASK_MIN is not set", true});
}

TEST(ShardEnvironment, SlurmArrayWithAStep) {
  // --array=0-12:4 runs tasks 0, 4, 8, 12
  auto task = [](const char* id, const char* step) {
    return Environment{{"SLURM_ARRAY_TASK_MIN", "0"}, {"SLURM_ARRAY_TASK_COUNT", "4"},
                       {"SLURM_ARRAY_TASK_STEP", step}, {"SLURM_ARRAY_TASK_ID", id}};
  };
  Check({task("8", "4"), "3/4",
         "Slurm SLURM_ARRAY_TASK_ID=8 SLURM_ARRAY_TASK_MIN=0 SLURM_ARRAY_TASK_COUNT=4 SLURM_ARRAY_TASK_STEP=4"});
  Check({task("6", "4"), "", "Slurm SLURM_ARRAY_TASK_ID=6", true});  // not on the step: a list like 0,6
  Check({task("6", "0"), "", "Slurm SLURM_ARRAY_TASK_ID=6", true});
}

TEST(ShardEnvironment, KubernetesIndexedJobIsZeroBasedWithTheCountGiven) {
  Check({{{"JOB_COMPLETION_INDEX", "0"}, {"URDFSNAP_SHARD_COUNT", "3"}}, "1/3",
         "Kubernetes JOB_COMPLETION_INDEX=0 URDFSNAP_SHARD_COUNT=3"});
  Check({{{"JOB_COMPLETION_INDEX", "2"}, {"URDFSNAP_SHARD_COUNT", "3"}}, "3/3",
         "Kubernetes JOB_COMPLETION_INDEX=2 URDFSNAP_SHARD_COUNT=3"});
  Check({{{"JOB_COMPLETION_INDEX", "3"}, {"URDFSNAP_SHARD_COUNT", "3"}}, "",
         "Kubernetes JOB_COMPLETION_INDEX=3 URDFSNAP_SHARD_COUNT=3: the shard index must be from 1 "
         "to 3, got 4", true});
  Check({{{"JOB_COMPLETION_INDEX", "-1"}, {"URDFSNAP_SHARD_COUNT", "3"}}, "",
         "Kubernetes JOB_COMPLETION_INDEX=-1 URDFSNAP_SHARD_COUNT=3: the shard index must be", true});
  Check({{{"JOB_COMPLETION_INDEX", "1"}}, "",
         "Kubernetes Indexed Job: JOB_COMPLETION_INDEX=1 is set (0-based), so the shard count must "
         "be given as URDFSNAP_SHARD_COUNT", true});
  Check({{{"URDFSNAP_SHARD_COUNT", "3"}}, "",
         "environment variable URDFSNAP_SHARD_COUNT=3 is set but JOB_COMPLETION_INDEX is not", true});
}

TEST(ShardEnvironment, SlurmThenKubernetesThenGitLab) {
  Check({{{"SLURM_ARRAY_TASK_ID", "1"}, {"SLURM_ARRAY_TASK_MIN", "1"}, {"SLURM_ARRAY_TASK_COUNT", "2"},
          {"JOB_COMPLETION_INDEX", "0"}, {"URDFSNAP_SHARD_COUNT", "3"},
          {"CI_NODE_INDEX", "4"}, {"CI_NODE_TOTAL", "4"}},
         "1/2", "Slurm SLURM_ARRAY_TASK_ID=1 SLURM_ARRAY_TASK_MIN=1 SLURM_ARRAY_TASK_COUNT=2"});
  Check({{{"JOB_COMPLETION_INDEX", "0"}, {"URDFSNAP_SHARD_COUNT", "3"},
          {"CI_NODE_INDEX", "4"}, {"CI_NODE_TOTAL", "4"}},
         "1/3", "Kubernetes JOB_COMPLETION_INDEX=0 URDFSNAP_SHARD_COUNT=3"});
}

TEST(ChooseShard, FlagWinsNoShardIgnoresTheEnvironment) {
  const Environment gitlab = {{"CI_NODE_INDEX", "3"}, {"CI_NODE_TOTAL", "4"}};
  const Environment broken = {{"CI_NODE_INDEX", "9"}, {"CI_NODE_TOTAL", "4"}};
  ShardChoice c = ChooseShard("1/2", false, Lookup(gitlab));
  EXPECT_EQ(ShardText(c.shard), "1/2");
  EXPECT_EQ(c.source, "--shard");
  c = ChooseShard(std::nullopt, false, Lookup(gitlab));
  EXPECT_EQ(ShardText(c.shard), "3/4");
  EXPECT_TRUE(c.sharded());
  c = ChooseShard(std::nullopt, true, Lookup(broken));  // not even read
  EXPECT_EQ(ShardText(c.shard), "1/1");
  EXPECT_FALSE(c.sharded());
  c = ChooseShard("2/2", false, Lookup(broken));
  EXPECT_EQ(ShardText(c.shard), "2/2");
  EXPECT_THROW(ChooseShard("0/3", false, Lookup(gitlab)), Error);
  EXPECT_THROW(ChooseShard(std::nullopt, false, Lookup(broken)), Error);
  EXPECT_FALSE(ChooseShard(std::nullopt, false, Lookup({})).sharded());
}

}  // namespace
}  // namespace urdfsnap::shard
