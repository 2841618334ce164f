// A robot's motion as urdfsnap animates it: for each joint it names, samples of its position over
// time, read from a CSV table, a JointTrajectory (MoveIt's plans), a stream of JointState messages
// or a bag. Joints keep their own sample times, so messages that name different joints (an arm's
// and a gripper's publisher on one topic) make one trajectory. Positions between samples are
// interpolated linearly, or, for a recording, hold until the next sample.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace urdfsnap::motion {

// What the sample times count.
enum class TimeBase {
  kSeconds,  // seconds from the trajectory's start
  kRows,     // row numbers 0, 1, 2, ... of a table without a time column: one row per frame
};

// What a position between two samples is.
enum class Between {
  kLinear,  // interpolated linearly: a plan's waypoints, a table
  kHold,    // the earlier sample's: a recording, as a player shows the latest message at or before t
};

// The samples of one joint; times strictly increase, positions are finite.
struct JointTrack {
  std::string joint;
  std::vector<double> times;
  std::vector<double> positions;  // radians or metres, one per time
  // Where the input first names the joint ("plan.yaml:3", "bag.mcap: message 1 on ..."), for
  // errors found later, such as a joint the robot does not have.
  std::string named_at;
};

struct Trajectory {
  std::string source;  // the file it was read from
  TimeBase time_base = TimeBase::kSeconds;
  std::vector<JointTrack> tracks;  // one per joint, in the order the input first names them
  // for messages timed by their stamps (JointState streams, bags): the stamp of time 0, in
  // seconds since 1970
  std::optional<double> stamp_at_zero;
  Between between = Between::kLinear;

  // The latest sample time over all tracks (0 for a trajectory of one instant).
  double EndTime() const;
};

// The position of `track` at time `t`: between the two samples around t as `between` says (a
// sample within a nanosecond after t counts as at t), the first sample's position before it and
// the last sample's after it. `track` must have samples.
double PositionAt(const JointTrack& track, double t, Between between = Between::kLinear);

}  // namespace urdfsnap::motion
