// Trajectory end time and linear interpolation by binary search over a track's times.
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

double PositionAt(const JointTrack& track, double t) {
  const std::vector<double>& times = track.times;
  if (t <= times.front()) return track.positions.front();
  if (t >= times.back()) return track.positions.back();
  // times[i - 1] <= t < times[i]
  const std::size_t i = std::upper_bound(times.begin(), times.end(), t) - times.begin();
  const double fraction = (t - times[i - 1]) / (times[i] - times[i - 1]);
  return track.positions[i - 1] + fraction * (track.positions[i] - track.positions[i - 1]);
}

}  // namespace urdfsnap::motion
