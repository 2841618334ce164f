// A sequence of numbered files, one per frame (PNG frames, and depth or label images beside them):
// each frame written under a temporary name beside its own ("00042.png.part-XXXXXX"), all moved
// into place by Finish, and removed when the sequence is abandoned before: a failed run leaves
// no partial sequence, and files of an earlier run keep their bytes. A sequence drawn by worker
// processes (`animate --jobs`) is staged: the parent chooses the temporary suffix, each worker
// leaves its files under their temporary names, and the parent moves every one into place (or
// removes them all) at the end.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "video/frame_pattern.h"

namespace urdfsnap::video {

// Whose temporary names a sequence's files are written under, and who moves them into place.
struct Staging {
  std::string suffix;       // the temporary names' suffix (".part-XXXXXX"); "": a new random one
  bool for_parent = false;  // a worker's: Finish leaves the files for the process that chose `suffix`
};

class NumberedFiles {
 public:
  // Parses `pattern` (see FramePattern) and checks that its first file, number `first`, can be
  // written (making and removing a temporary file beside it). Throws Error "NAME: cannot write:
  // ..." otherwise. A shard of a sequence starts at the number of its first frame, so that its
  // files are named as in the whole sequence.
  explicit NumberedFiles(const std::string& pattern, std::int64_t first = 0, const Staging& staging = {});
  // Removes the files written so far unless Finish was called.
  ~NumberedFiles();

  NumberedFiles(const NumberedFiles&) = delete;
  NumberedFiles& operator=(const NumberedFiles&) = delete;

  // Writes the next frame's file (number first + count()) under its temporary name. Throws Error
  // naming the file.
  void Write(std::string_view bytes);
  // Moves every file written into place (a worker's staged files: leaves them for its parent).
  // Throws Error naming a file that cannot be moved.
  void Finish();
  // The parent's side of a staged sequence: the `count` files from `first` that its workers wrote
  // under this sequence's temporary names are now this object's, moved by Finish or removed.
  void Adopt(std::int64_t count) {
    count_ = count;
    adopted_ = true;
  }

  std::int64_t count() const { return count_; }
  const FramePattern& pattern() const { return pattern_; }

 private:
  std::string TemporaryName(std::int64_t number) const;

  FramePattern pattern_;
  std::string temporary_suffix_;  // one for the whole sequence
  std::int64_t first_;
  std::int64_t count_ = 0;
  bool for_parent_;
  bool adopted_ = false;
  bool finished_ = false;
};

}  // namespace urdfsnap::video
