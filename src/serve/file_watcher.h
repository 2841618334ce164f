// Noticing that a model's files changed, by comparing each file's modification time, size and
// inode with those of the last look (polling, not inotify: editors that save by writing a new file
// and renaming it over the old one, network and container mounts that deliver no inotify events,
// and files that do not exist yet all need no special case, and a model's few hundred files cost
// well under a millisecond a look).
#pragma once

#include <compare>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace urdfsnap::serve {

class FileWatcher {
 public:
  // Watches `files` from now on: a later Changed() compares with how they are now. Returns true
  // when one of them was watched before and has changed since the last look (while a reload was
  // reading it, say), so that the caller loads once more.
  bool Watch(const std::vector<std::string>& files);

  // True when a watched file was created, deleted, replaced or modified since Watch() (or since
  // the last Changed() that returned true, which takes the new state as the reference).
  bool Changed();

  // The watched files, sorted.
  std::vector<std::string> files() const;

 private:
  struct Stamp {
    bool exists = false;
    std::int64_t mtime_ns = 0;
    std::uintmax_t size = 0;
    std::uintmax_t inode = 0;
    auto operator<=>(const Stamp&) const = default;
  };
  static Stamp Look(const std::string& file);

  std::map<std::string, Stamp> stamps_;
};

}  // namespace urdfsnap::serve
