// ParseShard: "K/N" with 1 <= K <= N, everything else one clear error.
#include "shard/shard_spec.h"

#include <gtest/gtest.h>

#include "common/error.h"

namespace urdfsnap::shard {
namespace {

TEST(ShardSpec, ParsesKOverN) {
  const Shard s = ParseShard("2/4", "--shard");
  EXPECT_EQ(s.index, 2);
  EXPECT_EQ(s.count, 4);
  EXPECT_EQ(ShardText(s), "2/4");
  EXPECT_EQ(ShardText(ParseShard("1/1", "--shard")), "1/1");
  EXPECT_EQ(ShardText(ParseShard("1000000/1000000", "--shard")), "1000000/1000000");
}

TEST(ShardSpec, RefusesEverythingElseNamingWhatWasExpected) {
  struct Case {
    const char* text;
    const char* message;
  } cases[] = {
      {"0/3", "--shard: the shard index must be from 1 to 3, got 0"},
      {"4/3", "--shard: the shard index must be from 1 to 3, got 4"},
      {"1/0", "--shard: the shard count must be from 1 to 1000000, got 0"},
      {"1/1000001", "--shard: the shard count must be from 1 to 1000000, got 1000001"},
      {"a/b", "--shard: expected K/N, two whole numbers with 1 <= K <= N (e.g. 2/4)"},
      {"", "--shard: expected K/N"},
      {"3", "--shard: expected K/N"},
      {"/3", "--shard: expected K/N"},
      {"1/", "--shard: expected K/N"},
      {"1/2/3", "--shard: expected K/N"},
      {"-1/3", "--shard: expected K/N"},
      {"+1/3", "--shard: expected K/N"},
      {" 1/3", "--shard: expected K/N"},
      {"1/3 ", "--shard: expected K/N"},
      {"1.0/3", "--shard: expected K/N"},
      {"99999999999999999999/3", "--shard: expected K/N"},
  };
  for (const Case& c : cases) {
    try {
      ParseShard(c.text, "--shard");
      ADD_FAILURE() << "accepted '" << c.text << "'";
    } catch (const Error& e) {
      EXPECT_EQ(std::string(e.what()).rfind(c.message, 0), 0u) << c.text << ": " << e.what();
    }
  }
}

}  // namespace
}  // namespace urdfsnap::shard
