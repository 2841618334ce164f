// TfDisplay: the links' scene poses from forward kinematics, the other frames from TF.
#include "animation/tf_display.h"

#include "model/forward_kinematics.h"

namespace urdfsnap::animation {

TfDisplay::TfDisplay(motion::TfDisplayFrames frames, scene::TfOptions options)
    : frames_(std::move(frames)), options_(options) {
  if (options_.show_names) names_ = scene::MakeTfNameLabels(frames_.names(), options_);
}

void TfDisplay::AddTo(const render::RobotRenderer& robot, const std::vector<double>& positions,
                      const Eigen::Isometry3d& X_SF, double t, scene::Scene& scene, Warnings& warnings) const {
  const std::vector<Eigen::Isometry3d> X_SL =
      robot.scene().LinkPoses(model::ComputeLinkPoses(robot.robot(), positions), X_SF);
  scene::AddTfFrames(frames_.Poses(X_SL, t, warnings), frames_.parents(), options_, names_, scene);
}

}  // namespace urdfsnap::animation
