// RViz's orbit camera geometry (orbit_view_controller.cpp updateCamera, makePitchValid).
#include "scene/orbit_view.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace urdfsnap::scene {

namespace {

// RViz keeps pitch off the poles (orbit_view_controller.cpp L79-80) and distance ≥ 0.01
// (L214-217), so the view direction is never parallel to the yaw axis.
double ValidPitch(double pitch) {
  const double limit = std::numbers::pi / 2 - 0.001;
  return std::clamp(pitch, -limit, limit);
}

double ValidDistance(double distance) { return std::max(distance, 0.01); }

}  // namespace

Eigen::Vector3d EyePosition(const OrbitView& view) {
  const double pitch = ValidPitch(view.pitch);
  const double d = ValidDistance(view.distance);
  return view.focal + d * Eigen::Vector3d(std::cos(view.yaw) * std::cos(pitch),
                                          std::sin(view.yaw) * std::cos(pitch), std::sin(pitch));
}

Eigen::Matrix4d ViewMatrix(const OrbitView& view) {
  const Eigen::Vector3d eye = EyePosition(view);
  const Eigen::Vector3d forward = (view.focal - eye).normalized();
  const Eigen::Vector3d right = forward.cross(Eigen::Vector3d::UnitZ()).normalized();
  const Eigen::Vector3d up = right.cross(forward);
  Eigen::Matrix4d X_CW = Eigen::Matrix4d::Identity();
  X_CW.block<1, 3>(0, 0) = right.transpose();
  X_CW.block<1, 3>(1, 0) = up.transpose();
  X_CW.block<1, 3>(2, 0) = -forward.transpose();
  X_CW.block<3, 1>(0, 3) = -X_CW.block<3, 3>(0, 0) * eye;
  return X_CW;
}

Eigen::Matrix4d ProjectionMatrix(const OrbitView& view, double aspect) {
  const double f = 1.0 / std::tan(view.fov_y / 2);
  const double n = view.near_clip;
  const double far = view.far_clip;
  Eigen::Matrix4d P = Eigen::Matrix4d::Zero();
  P(0, 0) = f / aspect;
  P(1, 1) = f;
  P(2, 2) = (far + n) / (n - far);
  P(2, 3) = 2 * far * n / (n - far);
  P(3, 2) = -1;
  return P;
}

}  // namespace urdfsnap::scene
