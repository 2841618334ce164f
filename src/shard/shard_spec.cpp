// ParseShard and its range check, shared with the environment reader.
#include "shard/shard_spec.h"

#include <charconv>

#include "common/error.h"

namespace urdfsnap::shard {

namespace {

// A whole number filling all of `text` (no sign, no spaces), or nullopt-like false.
bool ParseWhole(std::string_view text, long long& out) {
  if (text.empty()) return false;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), out);
  return error == std::errc() && end == text.data() + text.size() && out >= 0;
}

}  // namespace

Shard CheckedShard(long long index, long long count, const std::string& what) {
  if (count < 1 || count > kMaxShardCount) {
    throw Error(what + ": the shard count must be from 1 to " + std::to_string(kMaxShardCount) +
                ", got " + std::to_string(count));
  }
  if (index < 1 || index > count) {
    throw Error(what + ": the shard index must be from 1 to " + std::to_string(count) + ", got " +
                std::to_string(index));
  }
  return Shard{static_cast<int>(index), static_cast<int>(count)};
}

Shard ParseShard(std::string_view text, const std::string& what) {
  const std::size_t slash = text.find('/');
  long long index = 0, count = 0;
  if (slash == std::string_view::npos || !ParseWhole(text.substr(0, slash), index) ||
      !ParseWhole(text.substr(slash + 1), count)) {
    throw Error(what + ": expected K/N, two whole numbers with 1 <= K <= N (e.g. 2/4)");
  }
  return CheckedShard(index, count, what);
}

std::string ShardText(Shard shard) {
  return std::to_string(shard.index) + "/" + std::to_string(shard.count);
}

}  // namespace urdfsnap::shard
