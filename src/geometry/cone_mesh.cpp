// The unit cone of RViz's arrow heads (rviz_cone.mesh): smooth side, flat base.
#include "geometry/internal/circle_parts.h"
#include "geometry/triangle_mesh.h"

namespace urdfsnap::geometry {

TriangleMesh MakeUnitCone(int segments) {
  internal::CheckSegments("MakeUnitCone", segments);
  TriangleMesh mesh;
  // the side normal at angle a is (cos a, sin a, r/h) normalised, with r = 0.5 and h = 1
  const auto side_normal = [](const Eigen::Vector2f& c) {
    return Eigen::Vector3f(c.x(), c.y(), 0.5f).normalized();
  };
  // side: base vertex 2k at angle k, apex vertex 2k+1 halfway to angle k+1 (the apex has no single
  // smooth normal, so each side triangle gets its own apex copy)
  for (int k = 0; k < segments; ++k) {
    const Eigen::Vector2f c = internal::CirclePoint(k, segments);
    const Eigen::Vector2f halfway = internal::CirclePoint(2 * k + 1, 2 * segments);
    mesh.positions.emplace_back(0.5f * c.x(), 0.5f * c.y(), -0.5f);
    mesh.normals.push_back(side_normal(c));
    mesh.positions.emplace_back(0.f, 0.f, 0.5f);
    mesh.normals.push_back(side_normal(halfway));
  }
  for (int k = 0; k < segments; ++k) {
    const auto base = static_cast<std::uint32_t>(2 * k);
    const auto next_base = static_cast<std::uint32_t>(2 * ((k + 1) % segments));
    mesh.indices.insert(mesh.indices.end(), {base, next_base, base + 1});
  }
  internal::AppendDiscFan(mesh, -0.5f, /*faces_up=*/false, segments);
  return mesh;
}

}  // namespace urdfsnap::geometry
