// AnimationFrames: the camera fitted over every frame; poses and views per frame.
#include "animation/animation_frames.h"

#include "render/turntable_fit.h"

namespace urdfsnap::animation {

AnimationFrames::AnimationFrames(const render::RobotRenderer& robot, const motion::FramePlan& plan,
                                 const motion::FramePoses& poses, const CameraRequest& camera,
                                 Warnings& warnings, SceneAdditions additions)
    : plan_(plan), poses_(poses), additions_(additions), size_(camera.size), turntable_(camera.turntable),
      view_(camera.view), camera_(camera.camera), camera_tf_(camera.camera_tf) {
  // motion::kMaxFrames keeps the count within FitView's int
  const int count = static_cast<int>(plan_.frame_count);
  if (camera.fit != render::Fit::kNone && additions_.follow) {
    warnings.Add("--fit frames the whole motion from one place: the view does not follow a frame (--follow, an "
                 ".rviz view's Target Frame)");
    additions_.follow = nullptr;
  }
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
  return additions_.root ? additions_.root->At(plan_.TrajectoryTime(k), warnings) : Eigen::Isometry3d::Identity();
}

scene::Scene AnimationFrames::Scene(const render::RobotRenderer& robot, std::int64_t k, Warnings& warnings) const {
  const std::vector<double> positions = Positions(k, warnings);
  const Eigen::Isometry3d X_SF = Place(k, warnings);
  scene::Scene scene = robot.Pose(positions, X_SF);
  if (additions_.tf) additions_.tf->AddTo(robot, positions, X_SF, plan_.TrajectoryTime(k), scene, warnings);
  if (additions_.displays) additions_.displays->AddTo(robot, positions, X_SF, plan_.TrajectoryTime(k), scene, warnings);
  return scene;
}

std::optional<render::CameraSettings> AnimationFrames::Camera(std::int64_t k, Warnings& warnings) const {
  if (!camera_) return camera_;
  render::CameraSettings placed = *camera_;
  if (camera_tf_) {
    // X_TR: the robot's root in the camera's TF frame T; the camera then hangs off the root link
    placed.pose = camera_tf_->At(plan_.TrajectoryTime(k), warnings).inverse() * camera_->pose;
    placed.frame = camera_tf_->root();
  }
  if (additions_.underlay) additions_.underlay->Attach(plan_.TrajectoryTime(k), placed, warnings);
  return placed;
}

scene::OrbitView AnimationFrames::View(std::int64_t k) const {
  scene::OrbitView view = view_;
  if (turntable_) view.yaw = plan_.TurntableYaw(k, view_.yaw);
  if (additions_.follow) {
    Warnings repeated;   // the pose's warnings, which Positions and Place give the caller as well
    view.focal += additions_.follow->Origin(Positions(k, repeated), Place(k, repeated), plan_.TrajectoryTime(k),
                                            repeated);
  }
  return view;
}

}  // namespace urdfsnap::animation
