// A fresh folder for one test, unique across processes (mkdtemp), so that test runs of several
// builds or checkouts on one machine never share files; removed with everything in it at the end.
#pragma once

#include <stdlib.h>

#include <filesystem>
#include <stdexcept>
#include <string>

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
    std::filesystem::remove_all(path_, ignored);
  }
  TempFolder(const TempFolder&) = delete;
  TempFolder& operator=(const TempFolder&) = delete;

  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace urdfsnap::test
