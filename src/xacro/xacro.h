// urdfsnap's xacro processor: expands a xacro file to URDF text in process, as ROS's xacro does
// (in-order processing, the whole xacro language, Python expression subset), plus the legacy
// unprefixed macro calls of ROS Melodic that the ROS tutorials rely on.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "common/warnings.h"

namespace urdfsnap::xacro {

struct Options {
  std::vector<std::pair<std::string, std::string>> args;  // NAME:=VALUE words
  std::map<std::string, std::string> packages;            // --package PKG=DIR
  bool xacro_ns = false;  // --xacro-ns: modern strict behaviour (no legacy unprefixed calls)

  // Limits that end hostile or runaway input with an error instead of exhausting memory.
  int max_include_depth = 100;                    // nested xacro:include
  int max_macro_depth = 330;  // nested macro calls (where Python's recursion limit stops xacro)
  size_t max_document_bytes = size_t{256} << 20;  // nodes and text created while expanding
};

struct Result {
  std::string xml;                        // the URDF document, banner included
  std::vector<std::string> dependencies;  // included files and loaded yaml files, in order
};

// Expands the xacro file at `path`; throws urdfsnap::Error naming file, line and include chain.
// Warnings (legacy calls, redefined globals, deprecated names, xacro.warning()) go to `warnings`.
Result ExpandFile(const std::string& path, const Options& options, Warnings& warnings);

// The `mappings` xacro takes from NAME:=VALUE words: an empty value and names starting with a
// single underscore (ROS private parameters) are ignored.
std::map<std::string, std::string> ArgMappings(const std::vector<std::pair<std::string, std::string>>& args);

}  // namespace urdfsnap::xacro
