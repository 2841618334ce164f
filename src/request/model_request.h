// Which robot to load: a URDF or xacro file with its xacro arguments and package folders, as the
// MODEL argument of `render` and `info` or the `model:` key of a snapshot suite case gives it.
#pragma once

#include <compare>
#include <map>
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

// Reads the file (expanding xacro when the name ends in .xacro, xacro arguments are given or the
// robot declares the xacro namespace) and loads the robot. Throws urdfsnap::Error.
model::Robot LoadModel(const ModelRequest& request, Warnings& warnings);

}  // namespace urdfsnap::request
