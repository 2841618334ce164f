// Pieces shared by the round primitives (cylinder, cone): points on the unit circle at equal
// angles and a flat disc as a triangle fan. Internal to the geometry library.
#pragma once

#include <Eigen/Core>
#include <string_view>

#include "geometry/triangle_mesh.h"

namespace urdfsnap::geometry::internal {

// Throws urdfsnap::Error naming `shape` unless segments >= 3.
void CheckSegments(std::string_view shape, int segments);

// The point (cos a, sin a) for a = 2*pi*k/segments (radians), so k = 0 is +X.
Eigen::Vector2f CirclePoint(int k, int segments);

// Appends a flat disc of radius 0.5 at height z (metres), facing +Z if `faces_up` else -Z, as a
// fan of `segments` triangles around a centre vertex; segments + 1 new vertices.
void AppendDiscFan(TriangleMesh& mesh, float z, bool faces_up, int segments);

}  // namespace urdfsnap::geometry::internal
