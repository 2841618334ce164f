// Building a Trajectory from messages one after the other, each naming joints with positions at
// one time: JointState messages from a `ros2 topic echo /joint_states` stream or a bag's topic,
// and the points of a JointTrajectory. Each joint gets the samples of the messages that name it.
// Checks each message as it arrives and says where a bad one is.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

#include "motion/trajectory.h"

namespace urdfsnap::motion {

class JointStateTracks {
 public:
  // `source` names the input for the trajectory and for "no messages" errors. Times count from
  // `origin_ns` (0 for a JointTrajectory's time_from_start), or from the first message's time when
  // it is not given (header stamps).
  explicit JointStateTracks(std::string source, std::optional<std::int64_t> origin_ns = {});

  // Adds one message: its time in nanoseconds (header.stamp), its names and positions. `where`
  // says where the message is ("states.yaml:40", "bag.mcap: message 12 on '/joint_states' (log
  // time ...)"); it is called only for errors and for the first mention of a joint. A message
  // without positions is skipped (it carries velocities or efforts only). Throws Error "WHERE: ..."
  // for name and position lists of different lengths, a joint named twice in one message, a NaN or
  // infinite position, or a time not after that joint's previous sample (a repeated time with the
  // same position is skipped: a state published twice).
  void Add(std::int64_t time_ns, std::span<const std::string> names,
           std::span<const double> positions, const std::function<std::string()>& where);

  // The trajectory, in seconds from the origin (or the earliest sample, if that is before it),
  // with the stamp of time 0 when the times were stamps.
  // Throws Error "SOURCE: no joint positions in it: an empty trajectory" when no message had any.
  Trajectory Finish() &&;

 private:
  Trajectory trajectory_;
  std::unordered_map<std::string, std::size_t> track_of_joint_;
  std::vector<std::int64_t> last_time_ns_;    // per track, for the increasing-time check
  std::vector<std::size_t> seen_in_message_;  // per track: the message that last named it
  std::size_t messages_ = 0;
  std::optional<std::int64_t> origin_ns_;
  bool stamped_;  // times are stamps (no origin given): the trajectory keeps its stamp_at_zero
};

}  // namespace urdfsnap::motion
