// FrameFiles: WriteFileAtomically per frame; the files are found again by number for removal, so
// nothing grows with the sequence's length.
#include "video/frame_files.h"

#include <unistd.h>

#include "common/atomic_file.h"

namespace urdfsnap::video {

FrameFiles::FrameFiles(const std::string& pattern, std::int64_t first) : pattern_(pattern), first_(first) {
  AtomicFile probe(pattern_.Name(first_));  // created and removed: the place is writable
}

FrameFiles::~FrameFiles() {
  if (finished_) return;
  for (std::int64_t number = first_; number < first_ + count_; ++number) {
    ::unlink(pattern_.Name(number).c_str());
  }
}

void FrameFiles::Write(std::string_view bytes) {
  WriteFileAtomically(pattern_.Name(first_ + count_), bytes);
  ++count_;
}

}  // namespace urdfsnap::video
