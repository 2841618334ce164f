// Which work belongs to a shard. Named items (snapshot cases) go by a stable hash of the name, so
// adding or removing a case never moves another one and each lands in exactly one shard for any
// N; frame sequences split into contiguous ranges, so each worker renders (and encodes) a run of
// consecutive frames.
#pragma once

#include <string_view>

#include "shard/shard_spec.h"

namespace urdfsnap::shard {

// The shard (1..count) that owns the item named `name`: 1 + StableHash(name) mod count.
int ShardOfName(std::string_view name, int count);

// True when `name` belongs to `shard`.
bool InShard(std::string_view name, Shard shard);

// Frames [first, end) of a sequence numbered 0..frame_count-1.
struct FrameRange {
  long long first = 0;
  long long end = 0;
  long long size() const { return end - first; }
};

// The contiguous frames of `shard`: shards K and K+1 meet without gap or overlap, together they
// cover every frame, and their sizes differ by at most one. A shard gets no frames when there are
// fewer frames than shards.
FrameRange FramesOfShard(long long frame_count, Shard shard);

}  // namespace urdfsnap::shard
