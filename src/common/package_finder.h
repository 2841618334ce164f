// Where a ROS package lives, without ROS: resolves `$(find PKG)` for xacro and, later,
// `package://PKG/...` mesh URIs.
#pragma once

#include <map>
#include <string>

namespace urdfsnap {

struct PackageSearch {
  // --package PKG=DIR: checked first.
  std::map<std::string, std::string> explicit_dirs;
  // The input file whose surroundings are searched last ("" for none).
  std::string near_file;
};

// Returns the absolute directory of package `name`, looked up in this order: the explicit map;
// every root of ROS_PACKAGE_PATH (crawled for package.xml files whose <name> is `name`);
// AMENT_PREFIX_PATH prefixes (PREFIX/share/NAME); then the ancestors of `search.near_file` (the
// nearest one whose package.xml names the package) and the siblings of the nearest package
// folder. Throws urdfsnap::Error "package 'NAME' not found, searched: ..." listing the places.
std::string FindPackage(const std::string& name, const PackageSearch& search);

// The <name> of the package.xml at `path`, or "" when it cannot be read.
std::string PackageXmlName(const std::string& path);

}  // namespace urdfsnap
