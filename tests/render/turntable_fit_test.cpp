// The turntable's one camera: the centre of the bounds of every frame, the distance that frames
// the robot from every yaw (no GL: fitting poses the prepared scene only) (unit).
#include "render/turntable_fit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>

namespace urdfsnap::render {
namespace {

// A long thin box along X: framed from the side it needs less distance than from the end.
RobotRenderer LongBox(Warnings& warnings) {
  auto robot = std::make_shared<const model::Robot>(model::LoadRobot(
      "<robot name=\"r\"><link name=\"a\"><visual><origin xyz=\"1 0 0.5\"/><geometry><box size=\"4 0.2 0.2\"/>"
      "</geometry></visual></link></robot>",
      "r.urdf", warnings));
  scene::SceneOptions options;
  options.grid.enabled = false;
  return RobotRenderer(robot, options, warnings);
}

TEST(TurntableFit, OneFocalPointAndTheDistanceThatFramesEverySide) {
  Warnings warnings;
  const RobotRenderer robot = LongBox(warnings);
  const ImageSize size{200, 100};
  const scene::OrbitView start;
  const int frames = 8;
  const auto pose = [](int) { return std::vector<double>{}; };
  const auto yaw = [&](int k) { return start.yaw + 2 * std::numbers::pi * k / frames; };
  const scene::OrbitView turntable = FitTurntable(robot, Fit::kFit, {}, start, size, frames, pose, yaw);
  EXPECT_TRUE(turntable.focal.isApprox(Eigen::Vector3d(1, 0, 0.5), 1e-9));
  EXPECT_DOUBLE_EQ(turntable.yaw, start.yaw);
  double widest = 0;
  for (int k = 0; k < frames; ++k) {
    scene::OrbitView side = turntable;
    side.yaw = yaw(k);
    widest = std::max(widest, robot.FitView(Fit::kKeepFocal, {}, side, size, 1, pose).distance);
  }
  EXPECT_DOUBLE_EQ(turntable.distance, widest);

  // without --fit the view is as given
  const scene::OrbitView unfitted = FitTurntable(robot, Fit::kNone, {}, start, size, frames, pose, yaw);
  EXPECT_EQ(unfitted.distance, start.distance);
  EXPECT_TRUE(unfitted.focal.isApprox(start.focal));
}

}  // namespace
}  // namespace urdfsnap::render
