// ShardFromEnvironment: one reader per job engine, each turning its variables into K/N.
#include "shard/shard_environment.h"

#include <charconv>
#include <cstdlib>
#include <string_view>

#include "common/error.h"

namespace urdfsnap::shard {

namespace {

// NAME=VALUE of a variable that is set.
std::string Assignment(const char* name, const char* value) {
  return std::string(name) + "=" + value;
}

// The value of variable `name` as a whole number (a leading '-' allowed, so that a negative index
// is reported as out of range rather than as garbage).
long long WholeNumber(const char* name, const char* value) {
  const std::string_view text(value);
  long long number = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), number);
  if (text.empty() || error != std::errc() || end != text.data() + text.size()) {
    throw Error("environment variable " + Assignment(name, value) + ": expected a whole number");
  }
  return number;
}

// A variable another one needs.
const char* Required(const EnvironmentLookup& lookup, const char* name, const std::string& because) {
  const char* value = lookup(name);
  if (!value) throw Error(because + " but " + name + " is not set");
  return value;
}

std::optional<ShardChoice> FromSlurm(const EnvironmentLookup& lookup) {
  const char* id = lookup("SLURM_ARRAY_TASK_ID");
  if (!id) return std::nullopt;
  const std::string because = "Slurm job array: " + Assignment("SLURM_ARRAY_TASK_ID", id) + " is set";
  const char* min = Required(lookup, "SLURM_ARRAY_TASK_MIN", because);
  const char* count = Required(lookup, "SLURM_ARRAY_TASK_COUNT", because);
  const char* step = lookup("SLURM_ARRAY_TASK_STEP");
  std::string source = "Slurm " + Assignment("SLURM_ARRAY_TASK_ID", id) + " " +
                       Assignment("SLURM_ARRAY_TASK_MIN", min) + " " +
                       Assignment("SLURM_ARRAY_TASK_COUNT", count);
  long long stride = 1;
  if (step) {
    source.append(" ").append(Assignment("SLURM_ARRAY_TASK_STEP", step));
    stride = WholeNumber("SLURM_ARRAY_TASK_STEP", step);
    if (stride < 1) throw Error(source + ": the step must be at least 1");
  }
  const long long offset = WholeNumber("SLURM_ARRAY_TASK_ID", id) - WholeNumber("SLURM_ARRAY_TASK_MIN", min);
  if (offset % stride != 0) {
    throw Error(source + ": the task is not on the array's step; submit a range "
                         "(--array=MIN-MAX or MIN-MAX:STEP), not a list of indices");
  }
  const Shard shard = CheckedShard(offset / stride + 1, WholeNumber("SLURM_ARRAY_TASK_COUNT", count), source);
  return ShardChoice{shard, source};
}

std::optional<ShardChoice> FromKubernetes(const EnvironmentLookup& lookup) {
  const char* index = lookup("JOB_COMPLETION_INDEX");
  if (!index) return std::nullopt;
  const char* count = Required(
      lookup, "URDFSNAP_SHARD_COUNT",
      "Kubernetes Indexed Job: " + Assignment("JOB_COMPLETION_INDEX", index) +
          " is set (0-based), so the shard count must be given as URDFSNAP_SHARD_COUNT (the Job's "
          "completions),");
  const std::string source = "Kubernetes " + Assignment("JOB_COMPLETION_INDEX", index) + " " +
                             Assignment("URDFSNAP_SHARD_COUNT", count);
  const Shard shard = CheckedShard(WholeNumber("JOB_COMPLETION_INDEX", index) + 1,
                                   WholeNumber("URDFSNAP_SHARD_COUNT", count), source);
  return ShardChoice{shard, source};
}

std::optional<ShardChoice> FromGitLab(const EnvironmentLookup& lookup) {
  // GitLab sets CI_NODE_TOTAL=1 in every job; CI_NODE_INDEX only in jobs made by parallel:
  const char* index = lookup("CI_NODE_INDEX");
  if (!index) return std::nullopt;
  const char* total = Required(lookup, "CI_NODE_TOTAL",
                               "GitLab parallel job: " + Assignment("CI_NODE_INDEX", index) + " is set");
  const std::string source =
      "GitLab " + Assignment("CI_NODE_INDEX", index) + " " + Assignment("CI_NODE_TOTAL", total);
  const Shard shard = CheckedShard(WholeNumber("CI_NODE_INDEX", index),
                                   WholeNumber("CI_NODE_TOTAL", total), source);
  return ShardChoice{shard, source};
}

}  // namespace

const char* ProcessEnvironment(const char* name) { return std::getenv(name); }

std::optional<ShardChoice> ShardFromEnvironment(const EnvironmentLookup& lookup) {
  for (const auto reader : {FromSlurm, FromKubernetes, FromGitLab}) {
    if (auto choice = reader(lookup)) return choice;
  }
  if (const char* count = lookup("URDFSNAP_SHARD_COUNT")) {
    throw Error("environment variable " + Assignment("URDFSNAP_SHARD_COUNT", count) +
                " is set but JOB_COMPLETION_INDEX is not: URDFSNAP_SHARD_COUNT is the shard "
                "count of a Kubernetes Indexed Job (elsewhere use --shard K/N)");
  }
  return std::nullopt;
}

ShardChoice ChooseShard(const std::optional<std::string>& flag, bool no_shard,
                        const EnvironmentLookup& lookup) {
  if (flag) {
    const Shard shard = ParseShard(*flag, "--shard '" + *flag + "'");
    return ShardChoice{shard, "--shard"};
  }
  if (!no_shard) {
    if (auto choice = ShardFromEnvironment(lookup)) return *choice;
  }
  return ShardChoice{};
}

}  // namespace urdfsnap::shard
