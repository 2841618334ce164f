// Temporary xacro files for tests.
#include "xacro_test_files.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "common/error.h"

namespace urdfsnap::xacro {

namespace fs = std::filesystem;

TestFiles::TestFiles() {
  std::string pattern = (fs::temp_directory_path() / "xacro_test.XXXXXX").string();
  dir_ = mkdtemp(pattern.data());
}

TestFiles::~TestFiles() {
  std::error_code ec;
  fs::remove_all(dir_, ec);
}

std::string TestFiles::Write(const std::string& name, const std::string& text) const {
  const fs::path path = fs::path(dir_) / name;
  fs::create_directories(path.parent_path());
  std::ofstream(path) << text;
  return path.string();
}

std::string ExpandText(const std::string& text, const Options& options, Warnings* warnings) {
  TestFiles files;
  Warnings local;
  return ExpandFile(files.Write("input.xacro", text), options, warnings ? *warnings : local).xml;
}

std::string ExpandError(const std::string& text, const Options& options) {
  try {
    ExpandText(text, options);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

}  // namespace urdfsnap::xacro
