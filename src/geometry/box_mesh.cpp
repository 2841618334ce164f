// The unit box: six flat faces of four vertices each, as rviz_cube.mesh.
#include "geometry/internal/texture_coordinates.h"
#include "geometry/triangle_mesh.h"

namespace urdfsnap::geometry {

TriangleMesh MakeUnitBox() {
  TriangleMesh mesh;
  for (int axis = 0; axis < 3; ++axis) {
    for (const float sign : {1.f, -1.f}) {
      // n is the outward normal; u x v = n makes the corner order below counter-clockwise
      const Eigen::Vector3f n = sign * Eigen::Vector3f::Unit(axis);
      const Eigen::Vector3f u = sign * Eigen::Vector3f::Unit((axis + 1) % 3);
      const Eigen::Vector3f v = Eigen::Vector3f::Unit((axis + 2) % 3);
      const auto first = static_cast<std::uint32_t>(mesh.positions.size());
      for (const auto& [su, sv] : {std::pair{-1.f, -1.f}, {1.f, -1.f}, {1.f, 1.f}, {-1.f, 1.f}}) {
        mesh.positions.push_back(0.5f * (n + su * u + sv * v));
        mesh.normals.push_back(n);
      }
      mesh.indices.insert(mesh.indices.end(),
                          {first, first + 1, first + 2, first, first + 2, first + 3});
    }
  }
  internal::AttachBoxUvs(mesh);
  return mesh;
}

}  // namespace urdfsnap::geometry
