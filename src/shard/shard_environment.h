// Which shard this process is: from --shard K/N, or from the variables a job engine gives each of
// its workers, so that the same command line runs in every worker.
//
//   Slurm job array       SLURM_ARRAY_TASK_ID, SLURM_ARRAY_TASK_MIN, SLURM_ARRAY_TASK_COUNT
//                         (and SLURM_ARRAY_TASK_STEP when the array has a step): K = (ID - MIN) /
//                         STEP + 1, N = COUNT
//   Kubernetes Indexed Job JOB_COMPLETION_INDEX (0-based): K = index + 1; N from
//                         URDFSNAP_SHARD_COUNT (Kubernetes does not export .spec.completions)
//   GitLab parallel: N    CI_NODE_INDEX (1-based) and CI_NODE_TOTAL
//
// Looked for in this order; the first engine whose index variable is set decides.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "shard/shard_spec.h"

namespace urdfsnap::shard {

// The shard a process takes and where it came from.
struct ShardChoice {
  Shard shard;         // 1/1 when not sharded
  std::string source;  // "--shard", "GitLab CI_NODE_INDEX=2 CI_NODE_TOTAL=4", ...; "" when not sharded

  bool sharded() const { return !source.empty(); }
};

// Looks up an environment variable: its value, or nullptr when it is not set (like getenv).
using EnvironmentLookup = std::function<const char*(const char* name)>;

// The process's environment (getenv).
const char* ProcessEnvironment(const char* name);

// The shard from the engine's variables, or nullopt when none is set. Throws urdfsnap::Error naming
// the variables for an index or count that is not a whole number, out of range, an index without
// its count (JOB_COMPLETION_INDEX without URDFSNAP_SHARD_COUNT) or a count without an index.
std::optional<ShardChoice> ShardFromEnvironment(const EnvironmentLookup& lookup);

// What a command takes: `flag` (the text of --shard, nullopt when not given) wins; then, unless
// `no_shard`, the environment; else the whole work (1/1, not sharded). Throws like ParseShard and
// ShardFromEnvironment.
ShardChoice ChooseShard(const std::optional<std::string>& flag, bool no_shard,
                        const EnvironmentLookup& lookup = ProcessEnvironment);

}  // namespace urdfsnap::shard
