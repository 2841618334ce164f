// Which robot to load: a URDF or xacro file with its xacro arguments and package folders, as the
// MODEL argument of `render` and `info` or the `model:` key of a snapshot suite case gives it.
#pragma once

#include <compare>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "common/warnings.h"
#include "model/robot.h"

namespace urdfsnap::request {

struct ModelRequest {
  std::string path;                                              // URDF or xacro file
  std::vector<std::pair<std::string, std::string>> xacro_args;   // NAME, VALUE (NAME:=VALUE)
  std::map<std::string, std::string> packages;                   // PKG -> DIR ($(find), package://)
  bool xacro_ns = false;  // modern xacro's rule: only xacro:-prefixed tags are macro calls

  // Requests that compare equal load the same robot (used as a cache key).
  auto operator<=>(const ModelRequest&) const = default;
};

struct LoadedModel {
  std::shared_ptr<const model::Robot> robot;
  std::vector<std::string> files;   // the model file, then the xacro includes and YAML files read
};

// Reads the file (expanding xacro when the name ends in .xacro, xacro arguments are given or the
// robot declares the xacro namespace) and loads the robot. Throws urdfsnap::Error.
LoadedModel LoadModel(const ModelRequest& request, Warnings& warnings);

}  // namespace urdfsnap::request
