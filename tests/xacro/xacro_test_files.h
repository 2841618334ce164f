// Test helper: a temporary folder to write small xacro files into, and shortcuts to expand them.
#pragma once

#include <string>

#include "common/warnings.h"
#include "xacro/xacro.h"

namespace urdfsnap::xacro {

class TestFiles {
 public:
  TestFiles();
  ~TestFiles();
  TestFiles(const TestFiles&) = delete;
  TestFiles& operator=(const TestFiles&) = delete;

  // Writes `text` to `name` (relative to the folder, subfolders created); returns the full path.
  std::string Write(const std::string& name, const std::string& text) const;
  const std::string& dir() const { return dir_; }

 private:
  std::string dir_;
};

// Expands `text` written as input.xacro in a fresh folder; returns the output XML.
std::string ExpandText(const std::string& text, const Options& options = {}, Warnings* warnings = nullptr);

// The message of the urdfsnap::Error that expanding `text` throws, or "" when it succeeds.
std::string ExpandError(const std::string& text, const Options& options = {});

}  // namespace urdfsnap::xacro
