// FitTurntable: the bounds' centre for the focal point, one fit per yaw for the distance.
#include "render/turntable_fit.h"

#include <algorithm>

#include "scene/view_fitting.h"

namespace urdfsnap::render {

scene::OrbitView FitTurntable(const RobotRenderer& robot, Fit fit, const FitMargin& margin,
                              const scene::OrbitView& view, ImageSize size, int count,
                              const std::function<std::vector<double>(int)>& pose,
                              const std::function<double(int)>& yaw,
                              const std::function<Eigen::Isometry3d(int)>& place) {
  if (fit == Fit::kNone) return view;
  const auto X_SF = [&](int k) { return place ? place(k) : Eigen::Isometry3d::Identity(); };
  scene::OrbitView fitted = view;
  if (fit == Fit::kFit) {
    const auto centre = scene::BoundsCentre(count, [&](int k) { return robot.Pose(pose(k), X_SF(k)); });
    if (!centre) return view;
    fitted.focal = *centre;
  }
  double distance = 0;
  for (int k = 0; k < count; ++k) {
    const std::vector<double> positions = pose(k);
    const Eigen::Isometry3d placed = X_SF(k);
    scene::OrbitView side = fitted;
    side.yaw = yaw(k);
    side = robot.FitView(Fit::kKeepFocal, margin, side, size, 1, [&](int) { return positions; },
                         [&](int) { return placed; });
    distance = std::max(distance, side.distance);
  }
  if (distance > 0) fitted.distance = distance;
  return fitted;
}

}  // namespace urdfsnap::render
