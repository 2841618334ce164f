// Frames kept on disk, compressed, for an encoder that needs two passes over an animation (a GIF's
// palette is made from every frame before the first one can be written): appended one by one and
// read back in order, so memory holds one frame whatever the animation's length. The file is
// unnamed (O_TMPFILE in the temporary folder, $TMPDIR or /tmp): it disappears when the store is
// closed or the process ends, however it ends.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "image/image.h"

namespace urdfsnap::video {

class FrameStore {
 public:
  // A store for frames of `width` x `height`. Throws Error (naming `output`, the file the frames
  // are for) when no temporary file can be made.
  FrameStore(int width, int height, std::string output);
  ~FrameStore();

  FrameStore(const FrameStore&) = delete;
  FrameStore& operator=(const FrameStore&) = delete;

  // Compresses and appends `frame` (of the store's size). Throws Error when the disk is full.
  void Append(const image::Image& frame);

  // Goes back to the first frame; Next then hands them out in order.
  void Rewind();
  // Fills `frame` with the next stored frame; false after the last.
  bool Next(image::Image& frame);

  std::int64_t count() const { return count_; }
  std::uint64_t stored_bytes() const { return stored_bytes_; }  // compressed, on disk

 private:
  int width_, height_;
  std::string output_;
  int fd_ = -1;
  std::int64_t count_ = 0;
  std::uint64_t stored_bytes_ = 0;
  std::uint64_t read_offset_ = 0;
  std::vector<std::uint8_t> compressed_;  // one frame's worth, reused
  void* compressor_ = nullptr;            // ZSTD_CCtx
  void* decompressor_ = nullptr;          // ZSTD_DCtx
};

}  // namespace urdfsnap::video
