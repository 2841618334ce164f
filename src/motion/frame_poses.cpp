// FramePoses: joint names checked once, limit excursions found from the samples, then per frame
// interpolation, silent clamping and model::ResolveJointPositions.
#include "motion/frame_poses.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/error.h"
#include "common/number_text.h"

namespace urdfsnap::motion {
namespace {

std::string When(const Trajectory& trajectory, std::size_t sample, double time) {
  if (trajectory.time_base == TimeBase::kRows) return "in row " + std::to_string(sample + 1);
  return "at " + FormatNumber(time) + " s";
}

}  // namespace

FramePoses::FramePoses(const model::Robot& robot, const Trajectory& trajectory,
                       model::NamedValues defaults, bool clamp, Warnings& warnings)
    : robot_(robot), trajectory_(trajectory), values_(std::move(defaults)), clamp_(clamp) {
  first_track_value_ = values_.size();
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  for (const JointTrack& track : trajectory.tracks) {
    // the robot's own check and message for an unknown joint, located in the trajectory
    try {
      Warnings ignored;
      model::ResolveJointPositions(robot, {{track.joint, 0.0}}, false, ignored);
    } catch (const Error& e) {
      throw Error(track.named_at + ": " + e.what());
    }
    values_.emplace_back(track.joint, 0.0);
    const model::Joint& joint = robot.joints()[robot.FindJoint(track.joint)];
    if (!clamp || !joint.has_limits) {
      track_limits_.emplace_back(-kInfinity, kInfinity);
      continue;
    }
    track_limits_.emplace_back(joint.lower, joint.upper);
    // the sample furthest outside the limits, if any
    double worst_excess = 0;
    std::size_t worst = 0;
    for (std::size_t i = 0; i < track.positions.size(); ++i) {
      const double excess =
          std::max(joint.lower - track.positions[i], track.positions[i] - joint.upper);
      if (excess > worst_excess) {
        worst_excess = excess;
        worst = i;
      }
    }
    if (worst_excess > 0) {
      warnings.Add("joint '" + joint.name + "': " + trajectory.source + " moves it to " +
                   FormatNumber(track.positions[worst]) + " " +
                   When(trajectory, worst, track.times[worst]) + ", outside its limits [" +
                   FormatNumber(joint.lower) + ", " + FormatNumber(joint.upper) +
                   "]; clamped in every frame as joint_state_publisher's slider would "
                   "(--no-clamp keeps it)");
    }
  }
}

std::vector<double> FramePoses::At(double t, Warnings& warnings) const {
  model::NamedValues values = values_;
  for (std::size_t i = 0; i < trajectory_.tracks.size(); ++i) {
    const auto [lower, upper] = track_limits_[i];
    values[first_track_value_ + i].second =
        std::clamp(PositionAt(trajectory_.tracks[i], t), lower, upper);
  }
  return model::ResolveJointPositions(robot_, values, clamp_, warnings);
}

}  // namespace urdfsnap::motion
