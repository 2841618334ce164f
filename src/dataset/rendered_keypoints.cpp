// KeypointsOfFrame: forward kinematics once, the camera placed, ProjectKeypoints.
#include "dataset/rendered_keypoints.h"

#include "dataset/keypoints_file.h"
#include "model/forward_kinematics.h"

namespace urdfsnap::dataset {

RenderedKeypoints KeypointsOfFrame(const render::RobotRenderer& robot, const std::vector<double>& positions,
                                   const render::CameraSettings& camera, const image::Frame& frame) {
  const std::vector<Eigen::Isometry3d> X_RL = model::ComputeLinkPoses(robot.robot(), positions);
  const Eigen::Isometry3d X_FC = robot.CameraPose(X_RL, camera);
  const Eigen::Isometry3d X_RC = X_RL[robot.scene().fixed_link()] * X_FC;
  return {X_FC, ProjectKeypoints(robot.robot(), X_RL, X_RC, *camera.model, frame.depth, frame.labels)};
}

std::string RenderedKeypointsJson(const render::RobotRenderer& robot, const std::vector<double>& positions,
                                  const render::CameraSettings& camera, const image::Frame& frame, int indent) {
  const RenderedKeypoints k = KeypointsOfFrame(robot, positions, camera, frame);
  return KeypointsJson(*camera.model, k.X_FC, k.keypoints, indent);
}

}  // namespace urdfsnap::dataset
