// The MODEL argument shared by `render` and `info` as typed: a URDF or xacro file, NAME:=VALUE
// words, --package PKG=DIR and --xacro-ns, turned into a request::ModelRequest.
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "request/model_request.h"

namespace urdfsnap::cli {

struct ModelSource {
  std::string path;
  std::vector<std::string> xacro_words;        // NAME:=VALUE
  std::vector<std::string> packages;           // PKG=DIR
  bool xacro_ns = false;

  // Adds MODEL (required unless `optional`: the command then checks it), the NAME:=VALUE words,
  // --package and --xacro-ns to a subcommand.
  void AddOptions(CLI::App& command, bool optional = false);
  // The words parsed; throws urdfsnap::Error for a word that is not NAME:=VALUE or PKG=DIR.
  request::ModelRequest ToRequest() const;
};

}  // namespace urdfsnap::cli
