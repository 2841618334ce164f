// FitTurntable: one fit over every frame for the focal point, one per yaw for the distance.
#include "render/turntable_fit.h"

#include <algorithm>

namespace urdfsnap::render {

scene::OrbitView FitTurntable(const RobotRenderer& robot, Fit fit, const scene::OrbitView& view, ImageSize size,
                              int count, const std::function<std::vector<double>(int)>& pose,
                              const std::function<double(int)>& yaw,
                              const std::function<Eigen::Isometry3d(int)>& place) {
  scene::OrbitView fitted = robot.FitView(fit, view, size, count, pose, place);
  if (fit == Fit::kNone) return fitted;
  double distance = 0;
  for (int k = 0; k < count; ++k) {
    const std::vector<double> positions = pose(k);
    const Eigen::Isometry3d X_SF = place ? place(k) : Eigen::Isometry3d::Identity();
    scene::OrbitView side = fitted;
    side.yaw = yaw(k);
    side = robot.FitView(Fit::kKeepFocal, side, size, 1, [&](int) { return positions; },
                         [&](int) { return X_SF; });
    distance = std::max(distance, side.distance);
  }
  if (distance > 0) fitted.distance = distance;
  return fitted;
}

}  // namespace urdfsnap::render
