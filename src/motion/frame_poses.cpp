// FramePoses: joint names checked once, unknown ones set aside, limit excursions found from the
// samples, then per frame interpolation, clamping if asked and model::ResolveJointPositions.
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
  return "at " + FormatForPeople(time, "s");
}

// One warning when `track`'s samples leave `joint`'s limits: when they first leave, the furthest
// value and how far it is beyond.
void WarnOfExcursion(const Trajectory& trajectory, const JointTrack& track,
                     const model::Joint& joint, bool clamped, Warnings& warnings) {
  double worst_excess = 0;
  std::size_t worst = 0, first = track.positions.size();
  for (std::size_t i = 0; i < track.positions.size(); ++i) {
    const double excess =
        std::max(joint.lower - track.positions[i], track.positions[i] - joint.upper);
    if (excess > 0 && first == track.positions.size()) first = i;
    if (excess > worst_excess) {
      worst_excess = excess;
      worst = i;
    }
  }
  if (worst_excess <= 0) return;
  warnings.Add("joint '" + joint.name + "': " + trajectory.source + " takes it outside its limits, " +
               FormatRangeForPeople(joint.lower, joint.upper, joint.Unit()) + ", " +
               When(trajectory, first, track.times[first]) + ", furthest to " +
               FormatForPeople(track.positions[worst], joint.Unit()) + " " +
               When(trajectory, worst, track.times[worst]) + " (" + FormatForPeople(worst_excess, joint.Unit()) +
               " beyond); " +
               (clamped ? "clamped in every frame as joint_state_publisher's slider would"
                        : "drawn as recorded (--clamp clamps it)"));
}

// The defaults with every value clamped to its joint's limits as `render` clamps -j values, with
// its warnings; unknown joints throw as there.
model::NamedValues ClampedDefaults(const model::Robot& robot, model::NamedValues defaults,
                                   Warnings& warnings) {
  const std::vector<double> resolved =
      model::ResolveJointPositions(robot, defaults, true, warnings);
  for (auto& [name, value] : defaults) {
    const model::Joint& joint = robot.joints()[robot.FindJoint(name)];
    if (joint.IsMovable()) value = resolved[robot.FindJoint(name)];
  }
  return defaults;
}

}  // namespace

FramePoses::FramePoses(const model::Robot& robot, const Trajectory& trajectory,
                       model::NamedValues defaults, JointRules rules, Warnings& warnings)
    : robot_(robot),
      trajectory_(trajectory),
      values_(rules.clamp_defaults ? ClampedDefaults(robot, std::move(defaults), warnings)
                                   : std::move(defaults)) {
  first_track_value_ = values_.size();
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  // the robot's own check and message for an unknown joint, located in the trajectory
  const auto fail = [&](const JointTrack& track) {
    try {
      Warnings ignored;
      model::ResolveJointPositions(robot, {{track.joint, 0.0}}, false, ignored);
    } catch (const Error& e) {
      throw Error(track.named_at + ": " + e.what());
    }
  };
  std::string unknown;
  for (std::size_t i = 0; i < trajectory.tracks.size(); ++i) {
    const JointTrack& track = trajectory.tracks[i];
    const int j = robot.FindJoint(track.joint);
    if (j < 0) {
      if (rules.strict_joints) fail(track);
      unknown += (unknown.empty() ? "'" : ", '") + track.joint + "'";
      continue;
    }
    used_tracks_.push_back(i);
    values_.emplace_back(track.joint, 0.0);
    const model::Joint& joint = robot.joints()[j];
    const bool clamp = rules.clamp_trajectory && joint.has_limits;
    if (joint.has_limits && joint.IsMovable()) {
      WarnOfExcursion(trajectory, track, joint, clamp, warnings);
    }
    track_limits_.push_back(clamp ? std::pair(joint.lower, joint.upper)
                                  : std::pair(-kInfinity, kInfinity));
  }
  // a trajectory of another robot altogether is a mistake, not extra joints
  if (used_tracks_.empty() && !trajectory.tracks.empty()) fail(trajectory.tracks.front());
  if (!unknown.empty()) {
    warnings.Add(trajectory.source + ": joints robot '" + robot.name() +
                 "' does not have are ignored: " + unknown + " (--strict-joints stops instead)");
  }
}

std::vector<double> FramePoses::At(double t, Warnings& warnings) const {
  model::NamedValues values = values_;
  for (std::size_t i = 0; i < used_tracks_.size(); ++i) {
    const auto [lower, upper] = track_limits_[i];
    values[first_track_value_ + i].second =
        std::clamp(PositionAt(trajectory_.tracks[used_tracks_[i]], t, trajectory_.between), lower, upper);
  }
  return model::ResolveJointPositions(robot_, values, false, warnings);
}

}  // namespace urdfsnap::motion
