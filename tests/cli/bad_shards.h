// The bad shards every command that splits its work refuses alike (snapshot check/update, animate,
// docs): each with the one error line it must print after "urdfsnap: error: ", exit status 2.
#pragma once

#include <string>
#include <vector>

namespace urdfsnap::cli_test {

struct BadShard {
  std::string arguments;    // added to the command line
  std::string environment;  // "VAR=value ..." for RunUrdfsnap
  std::string message;
};

// --shard values out of range or not K/N, and each job engine's variables out of range, not
// numbers or without their count.
inline const std::vector<BadShard> kBadShards = {
    {"--shard 0/3", "", "--shard '0/3': the shard index must be from 1 to 3, got 0"},
    {"--shard 4/3", "", "--shard '4/3': the shard index must be from 1 to 3, got 4"},
    {"--shard a/b", "", "--shard 'a/b': expected K/N, two whole numbers with 1 <= K <= N (e.g. 2/4)"},
    {"--shard 3", "", "--shard '3': expected K/N, two whole numbers with 1 <= K <= N (e.g. 2/4)"},
    {"", "CI_NODE_INDEX=4 CI_NODE_TOTAL=3",
     "GitLab CI_NODE_INDEX=4 CI_NODE_TOTAL=3: the shard index must be from 1 to 3, got 4"},
    {"", "SLURM_ARRAY_TASK_ID=9 SLURM_ARRAY_TASK_MIN=5 SLURM_ARRAY_TASK_COUNT=4",
     "Slurm SLURM_ARRAY_TASK_ID=9 SLURM_ARRAY_TASK_MIN=5 SLURM_ARRAY_TASK_COUNT=4: the shard index "
     "must be from 1 to 4, got 5"},
    {"", "JOB_COMPLETION_INDEX=3 URDFSNAP_SHARD_COUNT=3",
     "Kubernetes JOB_COMPLETION_INDEX=3 URDFSNAP_SHARD_COUNT=3: the shard index must be from 1 to 3, got 4"},
    {"", "JOB_COMPLETION_INDEX=0",
     "Kubernetes Indexed Job: JOB_COMPLETION_INDEX=0 is set (0-based), so the shard count must be "
     "given as URDFSNAP_SHARD_COUNT (the Job's completions), but URDFSNAP_SHARD_COUNT is not set"},
    {"", "CI_NODE_INDEX=x CI_NODE_TOTAL=3", "environment variable CI_NODE_INDEX=x: expected a whole number"},
};

}  // namespace urdfsnap::cli_test
