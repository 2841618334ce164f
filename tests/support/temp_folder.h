// The one temporary-folder helper of the tests: a fresh folder for one test, unique across
// processes (mkdtemp), so that test runs of several builds or checkouts on one machine never share
// files; removed with everything in it at the end (permissions restored first, for tests that
// make it read-only).
#pragma once

#include <stdlib.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

namespace urdfsnap::test {

class TempFolder {
 public:
  // Creates TMPDIR/urdfsnap_<name>.XXXXXX.
  explicit TempFolder(const std::string& name) {
    std::string pattern =
        (std::filesystem::temp_directory_path() / ("urdfsnap_" + name + ".XXXXXX")).string();
    if (!mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed for " + pattern);
    path_ = pattern;
  }
  ~TempFolder() {
    std::error_code ignored;
    std::filesystem::permissions(path_, std::filesystem::perms::owner_all,
                                 std::filesystem::perm_options::add, ignored);
    std::filesystem::remove_all(path_, ignored);
  }
  TempFolder(const TempFolder&) = delete;
  TempFolder& operator=(const TempFolder&) = delete;

  const std::filesystem::path& path() const { return path_; }

  // The full path of `name` inside the folder.
  std::string Path(const std::string& name) const { return (path_ / name).string(); }

  // Writes `bytes` to `name` (subfolders created); returns the full path.
  std::string Write(const std::string& name, const std::string& bytes) const {
    const std::filesystem::path path = path_ / name;
    std::filesystem::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << bytes;
    return path.string();
  }

  // The bytes of `name` ("" when it cannot be read).
  std::string Read(const std::string& name) const {
    std::ifstream in(path_ / name, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  }

  // The names of the files in the folder, sorted: to check that no temporary file was left behind.
  std::vector<std::string> Listing() const {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(path_)) {
      names.push_back(entry.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
  }

 private:
  std::filesystem::path path_;
};

}  // namespace urdfsnap::test
