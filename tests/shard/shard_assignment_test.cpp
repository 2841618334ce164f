// Shard assignment by invariants: every case in exactly one shard for any N, nothing moves when a
// case is added, a fair balance; frame ranges contiguous and covering. The hash itself is pinned
// to values computed by an independent implementation of the documented algorithm, since changing
// it would reshuffle every user's shards.
#include "shard/shard_assignment.h"

#include <algorithm>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "common/stable_hash.h"

namespace urdfsnap::shard {
namespace {

std::vector<std::string> Names(int count, const std::string& prefix = "case_") {
  std::vector<std::string> names;
  for (int i = 0; i < count; ++i) names.push_back(prefix + std::to_string(i));
  return names;
}

TEST(ShardAssignment, HashIsTheDocumentedOne) {
  // FNV-1a 64 then SplitMix64's finalizer, computed in Python from the README's description
  EXPECT_EQ(StableHashText(""), "f52a15e9a9b5e89b");
  EXPECT_EQ(StableHashText("home"), "bf4bc9d24a581b40");
  EXPECT_EQ(StableHashText("case_00000"), "09c606395d75dada");
  EXPECT_EQ(StableHashText("case_00001"), "95bb17922c0881b8");
  EXPECT_EQ(ShardOfName("case_00000", 4), 3);
  EXPECT_EQ(ShardOfName("mrm_elbow", 3), 3);
  EXPECT_EQ(ShardOfName("home", 8), 1);
}

TEST(ShardAssignment, EveryNameInExactlyOneShardForAnyCount) {
  const auto names = Names(500);
  for (int count = 1; count <= 17; ++count) {
    for (const std::string& name : names) {
      int owners = 0;
      for (int index = 1; index <= count; ++index) owners += InShard(name, Shard{index, count});
      ASSERT_EQ(owners, 1) << name << " with " << count << " shards";
    }
  }
}

TEST(ShardAssignment, AddingCasesMovesNoOtherCase) {
  const auto before = Names(300);
  auto after = before;
  for (const auto& extra : Names(50, "new_")) after.insert(after.begin() + 7, extra);
  for (int count : {2, 5, 8}) {
    for (const std::string& name : before) {
      // the assignment depends on the name alone, not on the suite's other cases or their order
      EXPECT_EQ(ShardOfName(name, count), ShardOfName(std::string(name), count));
      EXPECT_TRUE(std::count(after.begin(), after.end(), name) == 1);
    }
  }
}

TEST(ShardAssignment, SequentialNamesSpreadEvenly) {
  // 8000 names like a generated suite's: each of 8 shards within 5% of the mean (1000)
  std::vector<int> sizes(8, 0);
  for (const auto& name : Names(8000)) ++sizes[ShardOfName(name, 8) - 1];
  for (int size : sizes) {
    EXPECT_GT(size, 950);
    EXPECT_LT(size, 1050);
  }
}

TEST(FrameRanges, ContiguousCoveringAndBalanced) {
  for (long long frames : {0LL, 1LL, 7LL, 100LL, 101LL, 1000LL}) {
    for (int count = 1; count <= 12; ++count) {
      long long next = 0, smallest = frames, largest = 0;
      for (int index = 1; index <= count; ++index) {
        const FrameRange r = FramesOfShard(frames, Shard{index, count});
        ASSERT_EQ(r.first, next) << frames << " frames, shard " << index << "/" << count;
        ASSERT_GE(r.size(), 0);
        smallest = std::min(smallest, r.size());
        largest = std::max(largest, r.size());
        next = r.end;
      }
      EXPECT_EQ(next, frames) << frames << " frames over " << count;
      EXPECT_LE(largest - smallest, 1) << frames << " frames over " << count;
    }
  }
  const FrameRange r = FramesOfShard(100, Shard{2, 4});
  EXPECT_EQ(r.first, 25);
  EXPECT_EQ(r.end, 50);
}

TEST(FrameRanges, HugeSequencesDoNotOverflow) {
  const long long frames = 4'000'000'000'000'000'000LL;
  const FrameRange last = FramesOfShard(frames, Shard{999'999, 1'000'000});
  EXPECT_EQ(last.end, frames - frames / 1'000'000);
  EXPECT_EQ(FramesOfShard(frames, Shard{1'000'000, 1'000'000}).end, frames);
}

}  // namespace
}  // namespace urdfsnap::shard
