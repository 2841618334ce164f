// A sequence of numbered files, one per frame (PNG frames, and depth or label images beside them):
// each file written atomically, and every file of the sequence removed again when it is abandoned
// before Finish, so that a failed run leaves no partial sequence.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "video/frame_pattern.h"

namespace urdfsnap::video {

class FrameFiles {
 public:
  // Parses `pattern` (see FramePattern) and checks that its first file, number `first`, can be
  // written (making and removing a temporary file beside it). Throws Error "NAME: cannot write:
  // ..." otherwise. A shard of a sequence starts at the number of its first frame, so that its
  // files are named as in the whole sequence.
  explicit FrameFiles(const std::string& pattern, std::int64_t first = 0);
  // Removes the files written so far unless Finish was called.
  ~FrameFiles();

  FrameFiles(const FrameFiles&) = delete;
  FrameFiles& operator=(const FrameFiles&) = delete;

  // Writes the next frame's file (number first + count()). Throws Error naming the file.
  void Write(std::string_view bytes);
  // Keeps the files.
  void Finish() { finished_ = true; }

  std::int64_t count() const { return count_; }
  const FramePattern& pattern() const { return pattern_; }

 private:
  FramePattern pattern_;
  std::int64_t first_;
  std::int64_t count_ = 0;
  bool finished_ = false;
};

}  // namespace urdfsnap::video
