// Test helper: a temporary folder to write small xacro files into, and shortcuts to expand them.
#pragma once

#include <string>

#include "common/warnings.h"
#include "support/temp_folder.h"
#include "xacro/xacro.h"

namespace urdfsnap::xacro {

// A temporary folder to write xacro files into (Write(name, text) returns the full path).
class TestFiles : public test::TempFolder {
 public:
  TestFiles() : TempFolder("xacro_test") {}
  std::string dir() const { return path().string(); }
};

// Expands `text` written as input.xacro in a fresh folder; returns the output XML.
std::string ExpandText(const std::string& text, const Options& options = {}, Warnings* warnings = nullptr);

// The message of the urdfsnap::Error that expanding `text` throws, or "" when it succeeds.
std::string ExpandError(const std::string& text, const Options& options = {});

}  // namespace urdfsnap::xacro
