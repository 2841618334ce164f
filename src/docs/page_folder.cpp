// PageFolder and ScratchFolder: mkdir with a random suffix, renameat2 to swap folders.
#include "docs/page_folder.h"

#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/stat.h>

#include <cerrno>
#include <system_error>

#include "common/atomic_file.h"
#include "common/error.h"
#include "common/file_reading.h"
#include "common/random_suffix.h"

namespace urdfsnap::docs {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void Fail(const fs::path& path, const std::string& what, int error_number) {
  throw Error(path.string() + ": " + what + ": " + std::system_category().message(error_number));
}

// True when `folder` holds an index.html made by urdfsnap docs.
bool HoldsPage(const fs::path& folder) {
  std::error_code error;
  if (!fs::is_regular_file(folder / "index.html", error)) return false;
  try {
    return ReadFileBounded((folder / "index.html").string()).find(kPageMarker) != std::string::npos;
  } catch (const FileReadError&) {
    return false;
  }
}

void CheckReplaceable(const fs::path& destination) {
  std::error_code error;
  const fs::file_status status = fs::symlink_status(destination, error);
  if (!fs::exists(status)) return;
  if (!fs::is_directory(status)) throw Error(destination.string() + ": exists and is not a folder");
  if (fs::is_empty(destination, error) || HoldsPage(destination)) return;
  throw Error(destination.string() +
              ": is a folder with other files than a page of urdfsnap docs (no index.html made by it); "
              "give a new or empty folder, it is replaced as a whole");
}

}  // namespace

PageFolder::PageFolder(fs::path destination) : destination_(std::move(destination)) {
  if (!destination_.has_filename()) destination_ = destination_.parent_path();   // "docs/page/"
  CheckReplaceable(destination_);
  std::error_code error;
  if (destination_.has_parent_path()) fs::create_directories(destination_.parent_path(), error);
  for (int attempt = 0;; ++attempt) {
    path_ = destination_.string() + ".tmp-" + RandomSuffix();
    if (::mkdir(path_.c_str(), 0777) == 0) break;
    if (errno != EEXIST || attempt == 100) Fail(destination_, "cannot write", errno);
  }
}

PageFolder::~PageFolder() {
  std::error_code ignored;
  if (!committed_) fs::remove_all(path_, ignored);
}

void PageFolder::Commit() {
  std::error_code error;
  if (!fs::exists(fs::symlink_status(destination_, error))) {
    if (::rename(path_.c_str(), destination_.c_str()) != 0) Fail(destination_, "cannot write", errno);
    committed_ = true;
    return;
  }
  CheckReplaceable(destination_);   // again: it may have changed while the page was made
  fs::path old = path_;
  if (::renameat2(AT_FDCWD, path_.c_str(), AT_FDCWD, destination_.c_str(), RENAME_EXCHANGE) != 0) {
    // no atomic swap on this file system: the older page moves aside first
    old = destination_.string() + ".old-" + RandomSuffix();
    if (::rename(destination_.c_str(), old.c_str()) != 0) Fail(destination_, "cannot replace", errno);
    if (::rename(path_.c_str(), destination_.c_str()) != 0) {
      const int rename_error = errno;
      ::rename(old.c_str(), destination_.c_str());
      Fail(destination_, "cannot replace", rename_error);
    }
  }
  committed_ = true;
  fs::remove_all(old, error);
}

ScratchFolder::ScratchFolder() {
  std::error_code error;
  std::string pattern = (fs::temp_directory_path(error) / "urdfsnap-docs-check.XXXXXX").string();
  if (error || !::mkdtemp(pattern.data())) Fail(pattern, "cannot make a temporary folder", errno);
  path_ = pattern;
}

ScratchFolder::~ScratchFolder() {
  std::error_code ignored;
  fs::remove_all(path_, ignored);
}

}  // namespace urdfsnap::docs
