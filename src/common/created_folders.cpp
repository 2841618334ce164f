// CreatedFolders: each missing ancestor made and remembered; rmdir in reverse order.
#include "common/created_folders.h"

#include <unistd.h>

#include <filesystem>
#include <system_error>

#include "common/error.h"

namespace urdfsnap {

namespace fs = std::filesystem;

CreatedFolders::~CreatedFolders() {
  for (auto it = made_.rbegin(); it != made_.rend(); ++it) ::rmdir(it->c_str());
}

void CreatedFolders::MakeParents(const std::string& file) {
  const fs::path parent = fs::path(file).parent_path();
  if (parent.empty()) return;
  std::vector<fs::path> missing;
  std::error_code error;
  for (fs::path folder = parent; !folder.empty() && !fs::exists(folder, error); folder = folder.parent_path()) {
    missing.push_back(folder);
    if (folder == folder.parent_path()) break;
  }
  for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
    if (!fs::create_directory(*it, error) && error) {
      throw Error(file + ": cannot make the folder '" + it->string() + "': " + error.message());
    }
    made_.push_back(it->string());
  }
}

}  // namespace urdfsnap
