// ShardOfName and FramesOfShard.
#include "shard/shard_assignment.h"

#include "common/stable_hash.h"

namespace urdfsnap::shard {

int ShardOfName(std::string_view name, int count) {
  return 1 + static_cast<int>(StableHash(name) % static_cast<unsigned>(count));
}

bool InShard(std::string_view name, Shard shard) {
  return ShardOfName(name, shard.count) == shard.index;
}

FrameRange FramesOfShard(long long frame_count, Shard shard) {
  // floor(frames * k / n) for k = K-1 and K; 128-bit so that no frame count overflows
  const auto boundary = [&](long long k) {
    return static_cast<long long>(static_cast<__int128>(frame_count) * k / shard.count);
  };
  return FrameRange{boundary(shard.index - 1), boundary(shard.index)};
}

}  // namespace urdfsnap::shard
