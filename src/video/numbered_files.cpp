// NumberedFiles: WriteFileAtomically per frame to its temporary name; the files are found again by
// number for the renames and removal, so nothing grows with the sequence's length.
#include "video/numbered_files.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <system_error>

#include "common/atomic_file.h"
#include "common/error.h"

namespace urdfsnap::video {

NumberedFiles::NumberedFiles(const std::string& pattern, std::int64_t first, const Staging& staging)
    : pattern_(pattern),
      temporary_suffix_(staging.suffix.empty() ? ".part-" + RandomSuffix() : staging.suffix),
      first_(first),
      for_parent_(staging.for_parent) {
  AtomicFile probe(pattern_.Name(first_));  // created and removed: the place is writable
}

NumberedFiles::~NumberedFiles() {
  if (finished_) return;
  if (adopted_) {
    // a staged sequence abandoned by the parent: its workers' files, and their temporary files
    // when a worker was stopped while writing one
    RemoveFilesNamedWith(std::filesystem::path(pattern_.Name(first_)).parent_path().string(), temporary_suffix_);
  }
  for (std::int64_t number = first_; number < first_ + count_; ++number) {
    ::unlink(TemporaryName(number).c_str());
  }
}

std::string NumberedFiles::TemporaryName(std::int64_t number) const {
  return pattern_.Name(number) + temporary_suffix_;
}

void NumberedFiles::Write(std::string_view bytes) {
  WriteFileAtomically(TemporaryName(first_ + count_), bytes);
  ++count_;
}

void NumberedFiles::Finish() {
  for (std::int64_t number = first_; number < first_ + count_ && !for_parent_; ++number) {
    if (std::rename(TemporaryName(number).c_str(), pattern_.Name(number).c_str()) != 0) {
      throw Error(pattern_.Name(number) + ": cannot write: " + std::system_category().message(errno));
    }
  }
  finished_ = true;
}

}  // namespace urdfsnap::video
