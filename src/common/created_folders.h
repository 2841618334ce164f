// The missing parent folders of a command's output files, made before the work starts and removed
// again when it fails, so that a failed run leaves nothing behind (`animate -o clips/arm.mp4` with
// no clips/ yet, `-o frames/%05d.png`).
#pragma once

#include <string>
#include <vector>

namespace urdfsnap {

class CreatedFolders {
 public:
  CreatedFolders() = default;
  // Removes the folders made, deepest first, unless Keep was called (those that are not empty stay).
  ~CreatedFolders();

  CreatedFolders(const CreatedFolders&) = delete;
  CreatedFolders& operator=(const CreatedFolders&) = delete;

  // Makes the folders missing above `file`. Throws urdfsnap::Error "FILE: cannot make the folder
  // 'DIR': <reason>".
  void MakeParents(const std::string& file);
  // The work succeeded: the folders stay.
  void Keep() { made_.clear(); }

 private:
  std::vector<std::string> made_;  // in the order made, parents first
};

}  // namespace urdfsnap
