// Where a docs page is written: a new folder beside its destination, moved into place only once
// the whole page is in it, so a failed run leaves neither a half-written page nor a damaged older
// one; and a scratch folder for the fresh page `--check` compares with.
#pragma once

#include <filesystem>

namespace urdfsnap::docs {

// The marker every index.html of `urdfsnap docs` carries; a folder is replaced only if it is
// empty or holds a page with it, so `-o` never deletes other files.
inline constexpr const char* kPageMarker = "<meta name=\"generator\" content=\"urdfsnap docs\">";

class PageFolder {
 public:
  // A new, empty folder "<destination>.tmp-XXXXXX" beside `destination` (mode 0777 less the
  // umask; missing parent folders are made). Throws urdfsnap::Error naming `destination` when it is a file, a folder that is not
  // empty and holds no page of `urdfsnap docs`, or when the folder cannot be made.
  explicit PageFolder(std::filesystem::path destination);
  // Removes the folder and everything in it unless Commit moved it into place.
  ~PageFolder();
  PageFolder(const PageFolder&) = delete;
  PageFolder& operator=(const PageFolder&) = delete;

  const std::filesystem::path& path() const { return path_; }

  // Moves the page into place: a folder at the destination is swapped with it in one step where
  // the file system can (Linux renameat2 RENAME_EXCHANGE), else renamed away first; the older page
  // is then removed. Throws urdfsnap::Error naming the destination.
  void Commit();

 private:
  std::filesystem::path destination_;
  std::filesystem::path path_;
  bool committed_ = false;
};

// A new folder under the system's temporary folder (TMPDIR), removed with its contents at the end.
class ScratchFolder {
 public:
  // Throws urdfsnap::Error when it cannot be made.
  ScratchFolder();
  ~ScratchFolder();
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;

  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace urdfsnap::docs
