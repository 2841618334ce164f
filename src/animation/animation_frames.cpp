// AnimationFrames: the camera fitted over every frame; poses and views per frame.
#include "animation/animation_frames.h"

#include <algorithm>

namespace urdfsnap::animation {

AnimationFrames::AnimationFrames(const render::RobotRenderer& robot, const motion::FramePlan& plan,
                                 const motion::FramePoses& poses, const CameraRequest& camera,
                                 Warnings& warnings)
    : plan_(plan), poses_(poses), size_(camera.size), turntable_(camera.turntable), view_(camera.view),
      camera_(camera.camera) {
  // motion::kMaxFrames keeps the count within FitView's int
  const int count = static_cast<int>(plan_.frame_count);
  const auto pose = [&](int k) { return Positions(k, warnings); };
  view_ = robot.FitView(camera.fit, camera.view, size_, count, pose);
  if (!turntable_ || camera.fit == render::Fit::kNone) return;

  // one focal point for every side (the centre of all frames' bounds, or the given one); the
  // distance that frames each frame from its own yaw, the largest of them kept
  double distance = 0;
  for (int k = 0; k < count; ++k) {
    const std::vector<double> positions = Positions(k, warnings);
    scene::OrbitView side = View(k);
    side = robot.FitView(render::Fit::kKeepFocal, side, size_, 1, [&](int) { return positions; });
    distance = std::max(distance, side.distance);
  }
  if (distance > 0) view_.distance = distance;
}

std::vector<double> AnimationFrames::Positions(std::int64_t k, Warnings& warnings) const {
  return poses_.At(plan_.TrajectoryTime(k), warnings);
}

scene::OrbitView AnimationFrames::View(std::int64_t k) const {
  scene::OrbitView view = view_;
  if (turntable_) view.yaw = plan_.TurntableYaw(k, view_.yaw);
  return view;
}

}  // namespace urdfsnap::animation
