// ShardPageImages: the files whose middle image lies in the shard's range of images.
#include "docs/page_shard.h"

#include "shard/shard_assignment.h"

namespace urdfsnap::docs {

std::vector<PageImage> ShardPageImages(const std::vector<PageImage>& files, shard::Shard shard) {
  const shard::FrameRange range = shard::FramesOfShard(ImageCount(files), shard);
  std::vector<PageImage> mine;
  std::int64_t first = 0;   // the first image of each file, counted over the whole page
  for (const PageImage& file : files) {
    const std::int64_t middle = first + file.images / 2;
    if (middle >= range.first && middle < range.end) mine.push_back(file);
    first += file.images;
  }
  return mine;
}

}  // namespace urdfsnap::docs
