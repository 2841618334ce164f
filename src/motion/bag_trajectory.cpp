// ReadBagTrajectory: bag::ReadJointStates into JointStateTracks.
#include "motion/bag_trajectory.h"

#include <limits>
#include <optional>

#include "bag/joint_state_bag.h"
#include "common/error.h"
#include "motion/joint_state_tracks.h"

namespace urdfsnap::motion {

Trajectory ReadBagTrajectory(const std::string& path, const std::string& topic,
                             Warnings& warnings) {
  JointStateTracks tracks(path);
  std::optional<bool> by_log_time;  // decided by the first message
  bag::ReadJointStates(path, topic, [&](const bag::BagJointState& state) {
    const auto where = [&] {
      return bag::DescribeMessage(state.file, topic, state.index, state.log_time);
    };
    if (!by_log_time) {
      by_log_time = state.message.StampNanoseconds() == 0;
      if (*by_log_time) {
        warnings.Add(path + ": header.stamp of the first message on '" + topic +
                     "' is zero; the messages are timed by their log times instead");
      }
    }
    if (*by_log_time && state.log_time > std::uint64_t{std::numeric_limits<std::int64_t>::max()}) {
      throw Error(where() + ": a log time beyond the year 2262");
    }
    tracks.Add(
        *by_log_time ? static_cast<std::int64_t>(state.log_time) : state.message.StampNanoseconds(),
        state.message.names, state.message.positions, where);
  });
  Trajectory trajectory = std::move(tracks).Finish();
  trajectory.between = Between::kHold;   // recorded states: a player shows the latest one
  return trajectory;
}

}  // namespace urdfsnap::motion
