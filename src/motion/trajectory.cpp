// Trajectory end time, and linear interpolation or the held sample by binary search over a track's times.
#include "motion/trajectory.h"

#include <algorithm>

namespace urdfsnap::motion {

double Trajectory::EndTime() const {
  double end = 0;
  for (const JointTrack& track : tracks) {
    if (!track.times.empty()) end = std::max(end, track.times.back());
  }
  return end;
}

double PositionAt(const JointTrack& track, double t, Between between) {
  // sample times are nanosecond stamps in seconds: a frame time rounded a little below a stamp is at it
  constexpr double kNanosecond = 1e-9;
  const std::vector<double>& times = track.times;
  if (t <= times.front()) return track.positions.front();
  if (t >= times.back() - (between == Between::kHold ? kNanosecond : 0)) return track.positions.back();
  if (between == Between::kHold) {
    const std::size_t i = std::upper_bound(times.begin(), times.end(), t + kNanosecond) - times.begin();
    return track.positions[i - 1];
  }
  // times[i - 1] <= t < times[i]
  const std::size_t i = std::upper_bound(times.begin(), times.end(), t) - times.begin();
  const double fraction = (t - times[i - 1]) / (times[i] - times[i - 1]);
  return track.positions[i - 1] + fraction * (track.positions[i] - track.positions[i - 1]);
}

}  // namespace urdfsnap::motion
