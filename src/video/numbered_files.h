// A sequence of numbered files, one per frame (PNG frames, and depth or label images beside them):
// each frame written under a temporary name beside its own ("00042.png.part-XXXXXX"), all moved
// into place by Finish, and removed when the sequence is abandoned before: a failed run leaves
// no partial sequence, and files of an earlier run keep their bytes.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "video/frame_pattern.h"

namespace urdfsnap::video {

class NumberedFiles {
 public:
  // Parses `pattern` (see FramePattern) and checks that its first file, number `first`, can be
  // written (making and removing a temporary file beside it). Throws Error "NAME: cannot write:
  // ..." otherwise. A shard of a sequence starts at the number of its first frame, so that its
  // files are named as in the whole sequence.
  explicit NumberedFiles(const std::string& pattern, std::int64_t first = 0);
  // Removes the files written so far unless Finish was called.
  ~NumberedFiles();

  NumberedFiles(const NumberedFiles&) = delete;
  NumberedFiles& operator=(const NumberedFiles&) = delete;

  // Writes the next frame's file (number first + count()) under its temporary name. Throws Error
  // naming the file.
  void Write(std::string_view bytes);
  // Moves every file written into place. Throws Error naming a file that cannot be moved.
  void Finish();

  std::int64_t count() const { return count_; }
  const FramePattern& pattern() const { return pattern_; }

 private:
  std::string TemporaryName(std::int64_t number) const;

  FramePattern pattern_;
  std::string temporary_suffix_;  // one for the whole sequence
  std::int64_t first_;
  std::int64_t count_ = 0;
  bool finished_ = false;
};

}  // namespace urdfsnap::video
