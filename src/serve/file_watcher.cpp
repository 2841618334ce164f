// One stat() per watched file and look.
#include "serve/file_watcher.h"

#include <sys/stat.h>

namespace urdfsnap::serve {

FileWatcher::Stamp FileWatcher::Look(const std::string& file) {
  struct stat info {};
  if (::stat(file.c_str(), &info) != 0) return {};
  return {true, std::int64_t{info.st_mtim.tv_sec} * 1'000'000'000 + info.st_mtim.tv_nsec,
          static_cast<std::uintmax_t>(info.st_size), static_cast<std::uintmax_t>(info.st_ino)};
}

bool FileWatcher::Watch(const std::vector<std::string>& files) {
  std::map<std::string, Stamp> stamps;
  bool changed = false;
  for (const auto& file : files) {
    const Stamp now = Look(file);
    const auto before = stamps_.find(file);
    if (before != stamps_.end() && before->second != now) changed = true;
    stamps[file] = now;
  }
  stamps_ = std::move(stamps);
  return changed;
}

bool FileWatcher::Changed() {
  bool changed = false;
  for (auto& [file, stamp] : stamps_) {
    const Stamp now = Look(file);
    if (now != stamp) changed = true;
    stamp = now;
  }
  return changed;
}

std::vector<std::string> FileWatcher::files() const {
  std::vector<std::string> files;
  for (const auto& [file, stamp] : stamps_) files.push_back(file);
  return files;
}

}  // namespace urdfsnap::serve
