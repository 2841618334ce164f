// FitTurntable: the bounds' centre for the focal point, then the distance from every yaw, each pose
// placed once for the frames that show it.
#include "render/turntable_fit.h"

#include <algorithm>
#include <vector>

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
  // frames showing the same pose at the same place (all of a still turntable) share one scene
  const double aspect = static_cast<double>(size.width) / size.height;
  double distance = 0;
  for (int k = 0; k < count;) {
    const std::vector<double> positions = pose(k);
    const Eigen::Isometry3d placed = X_SF(k);
    std::vector<double> yaws{yaw(k)};
    for (++k; k < count && pose(k) == positions && (!place || place(k).matrix() == placed.matrix()); ++k) {
      yaws.push_back(yaw(k));
    }
    distance =
        std::max(distance, scene::FitDistance(robot.Pose(positions, placed), fitted, yaws, aspect, margin.For(size)));
  }
  if (distance > 0) fitted.distance = distance;
  return fitted;
}

}  // namespace urdfsnap::render
