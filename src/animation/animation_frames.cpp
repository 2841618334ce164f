// AnimationFrames: the camera fitted over every frame; poses and views per frame.
#include "animation/animation_frames.h"

#include "render/turntable_fit.h"

namespace urdfsnap::animation {

AnimationFrames::AnimationFrames(const render::RobotRenderer& robot, const motion::FramePlan& plan,
                                 const motion::FramePoses& poses, const CameraRequest& camera,
                                 Warnings& warnings, const motion::RootPoses* root)
    : plan_(plan), poses_(poses), root_(root), size_(camera.size), turntable_(camera.turntable),
      view_(camera.view), camera_(camera.camera) {
  // motion::kMaxFrames keeps the count within FitView's int
  const int count = static_cast<int>(plan_.frame_count);
  const auto pose = [&](int k) { return Positions(k, warnings); };
  const auto place = [&](int k) { return Place(k, warnings); };
  if (!turntable_) {
    view_ = robot.FitView(camera.fit, camera.fit_margin, camera.view, size_, count, pose, place);
    return;
  }
  view_ = render::FitTurntable(robot, camera.fit, camera.fit_margin, camera.view, size_, count, pose,
                               [&](int k) { return plan_.TurntableYaw(k, camera.view.yaw); }, place);
}

std::vector<double> AnimationFrames::Positions(std::int64_t k, Warnings& warnings) const {
  return poses_.At(plan_.TrajectoryTime(k), warnings);
}

Eigen::Isometry3d AnimationFrames::Place(std::int64_t k, Warnings& warnings) const {
  return root_ ? root_->At(plan_.TrajectoryTime(k), warnings) : Eigen::Isometry3d::Identity();
}

scene::OrbitView AnimationFrames::View(std::int64_t k) const {
  scene::OrbitView view = view_;
  if (turntable_) view.yaw = plan_.TurntableYaw(k, view_.yaw);
  return view;
}

}  // namespace urdfsnap::animation
