// Which pictures and animations of a docs page a shard makes (docs --shard K/N): a contiguous run of
// them in page order, weighed by their images so that shards take about equal work, every file in
// exactly one shard. Each shard's folder holds its files and the page's two documents; the shards'
// folders copied into one are the whole page. The same for the pieces `docs --jobs` hands its workers,
// a joint section whole.
#pragma once

#include <vector>

#include "docs/page_images.h"
#include "shard/shard_spec.h"

namespace urdfsnap::docs {

// The files of `shard` among `files` (PageImages): those whose middle image falls in the shard's
// contiguous range of all the images (shard::FramesOfShard over ImageCount), so an animation goes
// whole to the shard that holds most of its frames. A shard may get no file when there are few of
// them (it then writes only the page's text).
std::vector<PageImage> ShardPageImages(const std::vector<PageImage>& files, shard::Shard shard);

// The files of piece `piece` of a page cut for `docs --jobs` workers: as ShardPageImages, but the
// files of one group (PageImage::group: a joint section's pictures and sweep) go whole to the piece
// holding their group's middle image, so that no section's camera is fitted in two pieces.
std::vector<PageImage> PiecePageImages(const std::vector<PageImage>& files, shard::Shard piece);

}  // namespace urdfsnap::docs
