// Writing a file so that readers see either the old file or the complete new one, never a partial
// or empty file: the bytes go to a temporary file beside the target, which is then renamed. Whole
// files in one call (WriteFileAtomically), or streams written piece by piece, also by a library
// that opens the temporary file by its name (AtomicFile: videos of any length).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "common/random_suffix.h"   // RandomSuffix, for temporary names beside an output

namespace urdfsnap {

// Writes `bytes` to "<path>.tmp-XXXXXX" (created new, mode 0666 less the umask) and renames it to
// `path`. On any failure the temporary file is removed, an existing file at `path` is left as it
// was, and urdfsnap::Error is thrown as "PATH: cannot write: <errno text>".
void WriteFileAtomically(const std::string& path, std::string_view bytes);

// Removes every file directly in `folder` whose name holds `part` (a random suffix only the
// temporary files of one run carry: those of worker processes stopped mid-write among them).
void RemoveFilesNamedWith(const std::string& folder, const std::string& part);

// A file that appears at `path` only when complete. The constructor creates the temporary file
// "<path>.tmp-XXXXXX" (so an unwritable place is an error before any work is done); Write appends
// to it, or another library writes it through temp_path(); Commit renames it to `path`. Destroyed
// without Commit (an error on the way), it removes the temporary file and leaves `path` as it was.
// Errors are urdfsnap::Error "PATH: cannot write: <errno text>".
class AtomicFile {
 public:
  explicit AtomicFile(std::string path);
  ~AtomicFile();

  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  // Appends `bytes` to the temporary file.
  void Write(std::string_view bytes);
  // Overwrites bytes already written at `offset` (a header whose sizes are known only at the end).
  void WriteAt(std::uint64_t offset, std::string_view bytes);
  // Closes the temporary file (no more writes); it stays until Commit or destruction, so that
  // many files can wait for their renames without as many open descriptors.
  void Close();
  // Closes the temporary file and renames it to path(); on failure removes it and throws.
  void Commit();

  const std::string& path() const { return path_; }
  const std::string& temp_path() const { return temp_path_; }

 private:
  std::string path_;
  std::string temp_path_;
  int fd_ = -1;
  bool committed_ = false;
};

}  // namespace urdfsnap
