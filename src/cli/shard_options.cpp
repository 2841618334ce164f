// ShardOptions: the two flags, their help naming the job engines, and the stderr line.
#include "cli/shard_options.h"

#include <cstdio>

#include "common/error.h"

namespace urdfsnap::cli {

void ShardOptions::AddOptions(CLI::App& command, const std::string& unit) {
  CLI::Option* flag = command.add_option(
      "--shard", shard,
      "take only shard K of N (1 <= K <= N) of the " + unit + ". Without it the shard comes from "
      "the job engine: Slurm arrays (SLURM_ARRAY_TASK_ID, _MIN, _COUNT), Kubernetes Indexed Jobs "
      "(JOB_COMPLETION_INDEX with URDFSNAP_SHARD_COUNT), GitLab parallel: (CI_NODE_INDEX, "
      "CI_NODE_TOTAL)");
  flag->type_name("K/N");
  command.add_flag("--no-shard", no_shard, "take all " + unit + ", whatever the environment says")
      ->excludes(flag);
}

shard::ShardChoice ShardOptions::Choose() const { return shard::ChooseShard(shard, no_shard); }

shard::ShardChoice ShardOptions::Choose(const std::string& indivisible) const {
  if (indivisible.empty()) return Choose();
  if (shard) throw Error("--shard '" + *shard + "': " + indivisible);
  const shard::ShardChoice environment = Choose();  // a bad variable is still an error
  if (environment.sharded()) {
    std::fprintf(stderr, "urdfsnap: not sharded: %s; shard %s from %s is set aside, all of it is done here\n",
                 indivisible.c_str(), shard::ShardText(environment.shard).c_str(), environment.source.c_str());
    std::fflush(stderr);
  }
  return {};
}

void PrintShardLine(const shard::ShardChoice& choice, std::size_t taken, std::size_t total,
                    const std::string& unit, const std::string& detail) {
  if (!choice.sharded()) return;
  const std::string note = detail.empty() ? "" : " (" + detail + ")";
  std::fprintf(stderr, "urdfsnap: shard %s from %s: %zu of %zu %s%s\n", shard::ShardText(choice.shard).c_str(),
               choice.source.c_str(), taken, total, unit.c_str(), note.c_str());
  std::fflush(stderr);
}

}  // namespace urdfsnap::cli
