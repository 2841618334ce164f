// JointStateTracks: per-joint sample lists with checks in integer nanoseconds (exact, whatever the
// epoch), converted to seconds from the first message.
#include "motion/joint_state_tracks.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "common/error.h"
#include "common/number_text.h"

namespace urdfsnap::motion {
namespace {

std::string Seconds(std::int64_t nanoseconds) {
  char text[48];
  std::snprintf(text, sizeof text, "%.9g s", nanoseconds * 1e-9);
  return text;
}

}  // namespace

JointStateTracks::JointStateTracks(std::string source, std::optional<std::int64_t> origin_ns)
    : origin_ns_(origin_ns), stamped_(!origin_ns) {
  trajectory_.source = std::move(source);
}

void JointStateTracks::Add(std::int64_t time_ns, std::span<const std::string> names,
                           std::span<const double> positions,
                           const std::function<std::string()>& where) {
  if (positions.empty()) return;
  ++messages_;
  if (names.size() != positions.size()) {
    throw Error(where() + ": " + std::to_string(names.size()) + " names but " +
                std::to_string(positions.size()) + " positions");
  }
  if (!origin_ns_) origin_ns_ = time_ns;
  const std::int64_t origin_ns = *origin_ns_;
  std::int64_t from_origin_ns = 0;
  if (__builtin_sub_overflow(time_ns, origin_ns, &from_origin_ns)) {
    throw Error(where() + ": a time too far from the first message's");
  }
  for (std::size_t i = 0; i < names.size(); ++i) {
    const std::string& joint = names[i];
    if (!std::isfinite(positions[i])) {
      throw Error(where() + ": joint '" + joint + "' has position " + FormatNumber(positions[i]) +
                  "; positions must be finite numbers");
    }
    auto [entry, is_new] = track_of_joint_.try_emplace(joint, trajectory_.tracks.size());
    if (is_new) {
      trajectory_.tracks.push_back(JointTrack{joint, {}, {}, where()});
      last_time_ns_.push_back(0);
      seen_in_message_.push_back(0);
    }
    const std::size_t t = entry->second;
    JointTrack& track = trajectory_.tracks[t];
    if (seen_in_message_[t] == messages_) {
      throw Error(where() + ": joint '" + joint + "' is named twice");
    }
    seen_in_message_[t] = messages_;
    if (!track.times.empty() && time_ns <= last_time_ns_[t]) {
      if (time_ns == last_time_ns_[t] && positions[i] == track.positions.back()) continue;
      throw Error(where() + ": joint '" + joint + "' at " + Seconds(from_origin_ns) +
                  " is not after its previous sample at " + Seconds(last_time_ns_[t] - origin_ns) +
                  " (times must increase)");
    }
    last_time_ns_[t] = time_ns;
    track.times.push_back(from_origin_ns * 1e-9);
    track.positions.push_back(positions[i]);
  }
}

Trajectory JointStateTracks::Finish() && {
  if (trajectory_.tracks.empty()) {
    throw Error(trajectory_.source + ": no joint positions in it: an empty trajectory");
  }
  // a joint's first sample may come before the origin (messages out of order across publishers,
  // a negative time_from_start): count from the earliest sample
  double earliest = 0;
  for (const JointTrack& track : trajectory_.tracks) earliest = std::min(earliest, track.times[0]);
  if (earliest < 0) {
    for (JointTrack& track : trajectory_.tracks) {
      for (double& time : track.times) time -= earliest;
    }
  }
  if (stamped_) trajectory_.stamp_at_zero = static_cast<double>(*origin_ns_) * 1e-9 + earliest;
  return std::move(trajectory_);
}

}  // namespace urdfsnap::motion
