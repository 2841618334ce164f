// Process-wide instances of the unit primitives (thread-safe function-local statics).
#include "scene/primitive_meshes.h"

namespace urdfsnap::scene {

namespace {
std::shared_ptr<const geometry::TriangleMesh> Share(geometry::TriangleMesh mesh) {
  return std::make_shared<const geometry::TriangleMesh>(std::move(mesh));
}
}  // namespace

const std::shared_ptr<const geometry::TriangleMesh>& UnitBoxMesh() {
  static const auto mesh = Share(geometry::MakeUnitBox());
  return mesh;
}

const std::shared_ptr<const geometry::TriangleMesh>& UnitCylinderMesh() {
  static const auto mesh = Share(geometry::MakeUnitCylinder());
  return mesh;
}

const std::shared_ptr<const geometry::TriangleMesh>& UnitSphereMesh() {
  static const auto mesh = Share(geometry::MakeUnitSphere());
  return mesh;
}


const std::shared_ptr<const geometry::TriangleMesh>& UnitConeMesh() {
  static const auto mesh = Share(geometry::MakeUnitCone());
  return mesh;
}

}  // namespace urdfsnap::scene
