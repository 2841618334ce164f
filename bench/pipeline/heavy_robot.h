// A generated mesh robot for the benchmarks: a chain of revolute links, each drawing a binary STL
// torus, with about `triangles` triangles in all (issue 5's 200,000-triangle robot).
#pragma once

#include <string>

namespace urdfsnap::bench {

// Writes DIR/heavy.urdf and DIR/meshes/link<i>.stl (file:// URIs); returns the URDF's path.
std::string WriteHeavyRobot(const std::string& dir, int triangles);

}  // namespace urdfsnap::bench
