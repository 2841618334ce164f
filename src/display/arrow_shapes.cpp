// Arrows and axes from the unit cylinder and cone (both along +Z, centred on the origin).
#include "display/arrow_shapes.h"

#include "scene/primitive_meshes.h"

namespace urdfsnap::display {
namespace {

// Turns the unit meshes' +Z onto +x and their x and y onto y and z.
Eigen::Matrix3d ZOntoX() {
  Eigen::Matrix3d R;
  R << 0, 0, 1,
       1, 0, 0,
       0, 1, 0;
  return R;
}

void AddPart(const std::shared_ptr<const geometry::TriangleMesh>& mesh, const Eigen::Isometry3d& X_FA,
             double start, double length, const Eigen::Vector2d& diameter, const Eigen::Vector4f& rgba,
             scene::Scene& scene) {
  Eigen::Affine3d X_FG(X_FA * Eigen::Translation3d(start + length / 2, 0, 0));
  X_FG.linear() = X_FG.linear() * ZOntoX() * Eigen::Vector3d(diameter.x(), diameter.y(), length).asDiagonal();
  scene.items.push_back({mesh, X_FG, rgba, -1, nullptr, 1, Eigen::Vector3f::Zero()});
}

}  // namespace

void AddArrow(const Eigen::Isometry3d& X_FA, const ArrowSize& size, const Eigen::Vector4f& rgba,
              scene::Scene& scene) {
  AddPart(scene::UnitCylinderMesh(), X_FA, 0, size.shaft_length, size.shaft_diameter, rgba, scene);
  AddPart(scene::UnitConeMesh(), X_FA, size.shaft_length, size.head_length, size.head_diameter, rgba, scene);
}

void AddAxes(const Eigen::Isometry3d& X_FA, double length, double diameter, float alpha,
             scene::Scene& scene) {
  // each axis is an arrow-less cylinder along x of a frame turned so that x is that axis
  const Eigen::Matrix3d turns[3] = {
      Eigen::Matrix3d::Identity(),
      Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix(),
      Eigen::AngleAxisd(-M_PI / 2, Eigen::Vector3d::UnitY()).toRotationMatrix()};
  for (int axis = 0; axis < 3; ++axis) {
    Eigen::Vector4f rgba(0, 0, 0, alpha);
    rgba[axis] = 1;
    Eigen::Isometry3d X_FX = X_FA;
    X_FX.linear() = X_FA.linear() * turns[axis];
    AddPart(scene::UnitCylinderMesh(), X_FX, 0, length, {diameter, diameter}, rgba, scene);
  }
}

}  // namespace urdfsnap::display
