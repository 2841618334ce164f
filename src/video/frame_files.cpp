// FrameFiles: WriteFileAtomically per frame; the files are found again by number for removal, so
// nothing grows with the sequence's length.
#include "video/frame_files.h"

#include <unistd.h>

#include "common/atomic_file.h"

namespace urdfsnap::video {

FrameFiles::FrameFiles(const std::string& pattern) : pattern_(pattern) {
  AtomicFile probe(pattern_.Name(0));  // created and removed: the place is writable
}

FrameFiles::~FrameFiles() {
  if (finished_) return;
  for (std::int64_t number = 0; number < count_; ++number) {
    ::unlink(pattern_.Name(number).c_str());
  }
}

void FrameFiles::Write(std::string_view bytes) {
  WriteFileAtomically(pattern_.Name(count_), bytes);
  ++count_;
}

}  // namespace urdfsnap::video
