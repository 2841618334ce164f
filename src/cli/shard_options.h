// --shard K/N and --no-shard for every command that splits its work over workers (snapshot
// check/update; animate and docs for frame sequences), and the stderr line saying which share a
// worker took and where its shard came from.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "shard/shard_environment.h"

namespace urdfsnap::cli {

struct ShardOptions {
  std::optional<std::string> shard;  // --shard K/N
  bool no_shard = false;             // --no-shard

  // Adds --shard and --no-shard to `command`; `unit` names the work in the help ("cases", "frames").
  void AddOptions(CLI::App& command, const std::string& unit);

  // The shard this run takes: --shard, else the job engine's variables (unless --no-shard), else
  // the whole work. Throws urdfsnap::Error for a bad --shard or environment value.
  shard::ShardChoice Choose() const;

  // Like Choose, for a run whose work is one piece after all; `indivisible` says why ("out.mp4 is
  // one file of every frame; ..."), "" when the work does split. --shard is then an error with
  // that reason; a shard from the environment (which may be meant for other commands of the same
  // job) is set aside with a note on stderr, and the whole work is taken.
  shard::ShardChoice Choose(const std::string& indivisible) const;
};

// When `choice` is sharded, prints "urdfsnap: shard 2/4 from GitLab CI_NODE_INDEX=2 CI_NODE_TOTAL=4:
// 251 of 1000 cases" on stderr, and " (DETAIL)" after it when `detail` is given.
void PrintShardLine(const shard::ShardChoice& choice, std::size_t taken, std::size_t total,
                    const std::string& unit, const std::string& detail = "");

}  // namespace urdfsnap::cli
