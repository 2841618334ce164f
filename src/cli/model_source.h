// The MODEL argument shared by `render` and `info`: a URDF file, or a xacro file expanded in
// process with NAME:=VALUE words, --package and --xacro-ns, loaded into a model::Robot.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "common/warnings.h"
#include "model/robot.h"

namespace urdfsnap::cli {

struct ModelSource {
  std::string path;
  std::vector<std::string> xacro_words;        // NAME:=VALUE
  std::vector<std::string> packages;           // PKG=DIR
  bool xacro_ns = false;

  // Adds MODEL, the NAME:=VALUE words, --package and --xacro-ns to a subcommand.
  void AddOptions(CLI::App& command);
  // Reads the file (expanding xacro when the name ends in .xacro or NAME:=VALUE words are given,
  // or the robot declares the xacro namespace) and loads the robot. Throws urdfsnap::Error.
  model::Robot Load(Warnings& warnings) const;
};

// "PKG=DIR" words to a map; throws urdfsnap::Error for a word without '='.
std::map<std::string, std::string> ParsePackageWords(const std::vector<std::string>& words);

}  // namespace urdfsnap::cli
