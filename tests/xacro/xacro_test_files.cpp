// Temporary xacro files for tests.
#include "xacro_test_files.h"

#include <filesystem>
#include <fstream>

#include "common/error.h"

namespace urdfsnap::xacro {

namespace fs = std::filesystem;


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
