// ShardPageImages and PiecePageImages: the files whose run (a file, or a group's files) has its
// middle image in the shard's range of images.
#include "docs/page_shard.h"

#include <functional>

#include "shard/shard_assignment.h"

namespace urdfsnap::docs {

namespace {

// The files of `shard` when each run of consecutive files with the same `key(i)` goes whole to
// the shard holding that run's middle image (counted over the whole page).
std::vector<PageImage> FilesOfShard(const std::vector<PageImage>& files, shard::Shard shard,
                                    const std::function<int(size_t)>& key) {
  const shard::FrameRange range = shard::FramesOfShard(ImageCount(files), shard);
  std::vector<PageImage> mine;
  std::int64_t first = 0;   // the first image of each run
  for (size_t begin = 0; begin < files.size();) {
    size_t end = begin;
    std::int64_t images = 0;
    for (; end < files.size() && key(end) == key(begin); ++end) images += files[end].images;
    const std::int64_t middle = first + images / 2;
    if (middle >= range.first && middle < range.end) mine.insert(mine.end(), files.begin() + begin, files.begin() + end);
    first += images;
    begin = end;
  }
  return mine;
}

}  // namespace

std::vector<PageImage> ShardPageImages(const std::vector<PageImage>& files, shard::Shard shard) {
  return FilesOfShard(files, shard, [](size_t i) { return static_cast<int>(i); });
}

std::vector<PageImage> PiecePageImages(const std::vector<PageImage>& files, shard::Shard piece) {
  return FilesOfShard(files, piece, [&](size_t i) { return files[i].group; });
}

}  // namespace urdfsnap::docs
