// Circle points and flat disc fans for the cylinder and the cone.
#include "geometry/internal/circle_parts.h"

#include <cmath>
#include <numbers>
#include <string>

#include "common/error.h"

namespace urdfsnap::geometry::internal {

void CheckSegments(std::string_view shape, int segments) {
  if (segments < 3) {
    throw Error(std::string(shape) + ": segments must be at least 3, got " +
                std::to_string(segments));
  }
}

Eigen::Vector2f CirclePoint(int k, int segments) {
  // angles in double so that the last point before 2*pi is as exact as the first
  const double angle = 2.0 * std::numbers::pi * k / segments;
  return {static_cast<float>(std::cos(angle)), static_cast<float>(std::sin(angle))};
}

void AppendDiscFan(TriangleMesh& mesh, float z, bool faces_up, int segments) {
  const auto centre = static_cast<std::uint32_t>(mesh.positions.size());
  const Eigen::Vector3f normal(0.f, 0.f, faces_up ? 1.f : -1.f);
  mesh.positions.emplace_back(0.f, 0.f, z);
  mesh.normals.push_back(normal);
  for (int k = 0; k < segments; ++k) {
    const Eigen::Vector2f p = 0.5f * CirclePoint(k, segments);
    mesh.positions.emplace_back(p.x(), p.y(), z);
    mesh.normals.push_back(normal);
  }
  // the ring runs counter-clockwise seen from +Z; a downward disc takes its triangles reversed
  for (int k = 0; k < segments; ++k) {
    const std::uint32_t a = centre + 1 + k;
    const std::uint32_t b = centre + 1 + (k + 1) % segments;
    if (faces_up) {
      mesh.indices.insert(mesh.indices.end(), {centre, a, b});
    } else {
      mesh.indices.insert(mesh.indices.end(), {centre, b, a});
    }
  }
}

}  // namespace urdfsnap::geometry::internal
