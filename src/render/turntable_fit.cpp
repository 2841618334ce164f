// FitTurntable: one fit over every frame for the focal point, then the distance from every yaw.
#include "render/turntable_fit.h"

#include <algorithm>
#include <vector>

#include "scene/view_fitting.h"

namespace urdfsnap::render {

scene::OrbitView FitTurntable(const RobotRenderer& robot, Fit fit, const scene::OrbitView& view, ImageSize size,
                              int count, const std::function<std::vector<double>(int)>& pose,
                              const std::function<double(int)>& yaw,
                              const std::function<Eigen::Isometry3d(int)>& place) {
  scene::OrbitView fitted = robot.FitView(fit, view, size, count, pose, place);
  if (fit == Fit::kNone) return fitted;
  // frames showing the same pose at the same place (all of a still turntable) share one scene
  const double aspect = static_cast<double>(size.width) / size.height;
  double distance = 0;
  for (int k = 0; k < count;) {
    const std::vector<double> positions = pose(k);
    const Eigen::Isometry3d X_SF = place ? place(k) : Eigen::Isometry3d::Identity();
    std::vector<double> yaws{yaw(k)};
    for (++k; k < count && pose(k) == positions && (!place || place(k).matrix() == X_SF.matrix()); ++k) {
      yaws.push_back(yaw(k));
    }
    distance = std::max(distance, scene::FitDistance(robot.Pose(positions, X_SF), fitted, yaws, aspect));
  }
  if (distance > 0) fitted.distance = distance;
  return fitted;
}

}  // namespace urdfsnap::render
