// Mesh URIs of URDF <mesh filename="..."> resolved to files without ROS: package://, file:// and
// plain paths.
#pragma once

#include <map>
#include <string>

namespace urdfsnap::geometry {

// Returns the file `uri` names:
//   package://PKG/REL  PKG's folder (common/package_finder.h: `packages` as --package PKG=DIR,
//                      ROS_PACKAGE_PATH, AMENT_PREFIX_PATH, then the package.xml folders around
//                      `model_file`) joined with REL;
//   file:///ABS        /ABS;
//   /ABS               as is;
//   REL                relative to the folder of `model_file` (the working folder when it is "").
// Throws urdfsnap::Error naming the URI and every place searched when the file does not exist (or
// is not a regular file), and for other schemes (http://, ...); the caller adds where the URI was
// written.
std::string ResolveMeshUri(const std::string& uri, const std::string& model_file,
                           const std::map<std::string, std::string>& packages);

// True for a URI without a scheme ("meshes/a.stl", "/abs/a.stl"): urdfsnap resolves it, but RViz
// and every ROS tool that uses resource_retriever do not.
bool IsPlainPath(const std::string& uri);

}  // namespace urdfsnap::geometry
