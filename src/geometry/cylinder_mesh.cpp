// The unit cylinder: rviz_cylinder.mesh's 40-segment side with smooth normals and two flat caps.
#include "geometry/internal/circle_parts.h"
#include "geometry/internal/texture_coordinates.h"
#include "geometry/triangle_mesh.h"

namespace urdfsnap::geometry {

TriangleMesh MakeUnitCylinder(int segments) {
  internal::CheckSegments("MakeUnitCylinder", segments);
  TriangleMesh mesh;
  // side: vertex 2k at the bottom, 2k+1 at the top, normals radial
  for (int k = 0; k < segments; ++k) {
    const Eigen::Vector2f c = internal::CirclePoint(k, segments);
    const Eigen::Vector3f normal(c.x(), c.y(), 0.f);
    for (const float z : {-0.5f, 0.5f}) {
      mesh.positions.emplace_back(0.5f * c.x(), 0.5f * c.y(), z);
      mesh.normals.push_back(normal);
    }
  }
  for (int k = 0; k < segments; ++k) {
    const auto bottom = static_cast<std::uint32_t>(2 * k);
    const auto next_bottom = static_cast<std::uint32_t>(2 * ((k + 1) % segments));
    mesh.indices.insert(mesh.indices.end(), {bottom, next_bottom, bottom + 1, bottom + 1,
                                             next_bottom, next_bottom + 1});
  }
  internal::AppendDiscFan(mesh, 0.5f, /*faces_up=*/true, segments);
  internal::AppendDiscFan(mesh, -0.5f, /*faces_up=*/false, segments);
  internal::AttachCylinderUvs(mesh);
  return mesh;
}

}  // namespace urdfsnap::geometry
