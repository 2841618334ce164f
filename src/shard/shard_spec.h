// A shard: worker K of N taking its share of a suite's cases or of a frame sequence, written
// "K/N" (1 <= K <= N) on the command line, in results files and in messages.
#pragma once

#include <string>
#include <string_view>

namespace urdfsnap::shard {

struct Shard {
  int index = 1;  // K, 1-based
  int count = 1;  // N; 1/1 is the whole work
};

// The largest N accepted: far above any fleet, small enough that no count overflows an int.
inline constexpr int kMaxShardCount = 1'000'000;

// Parses "K/N" (two whole numbers, 1 <= K <= N <= kMaxShardCount). Throws urdfsnap::Error
// beginning with `what` (e.g. "--shard '4/3'") and saying what was expected.
Shard ParseShard(std::string_view text, const std::string& what);

// Checks 1 <= index <= count <= kMaxShardCount; throws urdfsnap::Error beginning with `what`.
Shard CheckedShard(long long index, long long count, const std::string& what);

// "K/N".
std::string ShardText(Shard shard);

}  // namespace urdfsnap::shard
