// FrameDisplays: the feed advanced to the frame's stamp, the displays drawn through the bag's TF
// with the robot's posed links behind it.
#include "animation/frame_displays.h"

#include <cmath>
#include <utility>

#include "model/forward_kinematics.h"
#include "request/display_frame.h"

namespace urdfsnap::animation {

FrameDisplays::FrameDisplays(display::DisplaySet displays, const std::string& bag,
                             std::shared_ptr<const tf::TfBuffer> transforms, std::string fixed_frame,
                             double stamp_at_zero)
    : displays_(std::move(displays)), transforms_(std::move(transforms)), fixed_frame_(std::move(fixed_frame)),
      stamp_at_zero_(stamp_at_zero) {
  if (!bag.empty()) feed_.emplace(bag, displays_);
}

std::int64_t FrameDisplays::Stamp(double t) const {
  return static_cast<std::int64_t>(std::llround((stamp_at_zero_ + t) * 1e9));
}

void FrameDisplays::AddTo(const render::RobotRenderer& robot, const std::vector<double>& positions,
                          const Eigen::Isometry3d& X_SF, double t, scene::Scene& scene, Warnings& warnings) {
  const std::int64_t stamp = Stamp(t);
  shown_ns_ = stamp;
  if (feed_) feed_->AdvanceTo(stamp, warnings);
  const std::vector<Eigen::Isometry3d> X_RL = model::ComputeLinkPoses(robot.robot(), positions);
  const display::FrameLookup links = request::RobotFrames(robot.robot(), X_RL, robot.scene().fixed_link());
  const display::FrameLookup lookup = [&](const std::string& frame, std::int64_t time_ns) {
    if (const std::optional<tf::Lookup> found = transforms_->Find(fixed_frame_, frame, time_ns)) {
      return std::optional<Eigen::Isometry3d>(found->X_TS);
    }
    const std::optional<Eigen::Isometry3d> X_FL = links(frame, time_ns);
    return X_FL ? std::optional<Eigen::Isometry3d>(X_SF * *X_FL) : std::nullopt;
  };
  displays_.Draw(stamp, lookup, scene, warnings);
}

}  // namespace urdfsnap::animation
