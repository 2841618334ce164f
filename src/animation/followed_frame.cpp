// FollowedFrame: a link's origin by forward kinematics, another frame's through the bag's TF.
#include "animation/followed_frame.h"

#include <algorithm>

#include "common/error.h"
#include "model/forward_kinematics.h"

namespace urdfsnap::animation {

FollowedFrame::FollowedFrame(const render::RobotRenderer& robot, const std::string& frame,
                             std::optional<motion::TfDisplayFrames> tf)
    : robot_(robot), tf_(std::move(tf)) {
  const std::vector<std::string> names = tf_ ? tf_->names() : robot.robot().LinkNames();
  const auto found = std::find(names.begin(), names.end(), frame);
  if (found == names.end()) {
    throw Error("--follow '" + frame + "': neither a link of robot '" + robot.robot().name() + "'" +
                (tf_ ? std::string(" nor a frame the bag's TF connects to it") : std::string(" (frames outside "
                "the robot are followed through a bag's TF)")));
  }
  index_ = static_cast<std::size_t>(found - names.begin());
}

Eigen::Vector3d FollowedFrame::Origin(const std::vector<double>& positions, const Eigen::Isometry3d& X_SF, double t,
                                      Warnings& warnings) const {
  const std::vector<Eigen::Isometry3d> X_SL =
      robot_.scene().LinkPoses(model::ComputeLinkPoses(robot_.robot(), positions), X_SF);
  if (index_ < X_SL.size()) return X_SL[index_].translation();
  return tf_->Poses(X_SL, t, warnings)[index_].translation();
}

}  // namespace urdfsnap::animation
