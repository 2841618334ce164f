// Which frames an animation has and what each shows: frames at t = k / fps for k = 0 ... floor(T *
// fps), where T is the trajectory's length divided by the playback speed, the trajectory time each
// frame samples, and the camera's yaw for a turntable that turns once around over the animation.
#pragma once

#include <cstdint>
#include <optional>

#include "motion/trajectory.h"

namespace urdfsnap::motion {

// Frame rates above this are refused (no display or format shows them).
inline constexpr double kMaxFramesPerSecond = 1000;
// The most frames one animation may have: ten hours at 300 frames/s; more is taken for a
// mistake (a trajectory in nanoseconds read as seconds).
inline constexpr std::int64_t kMaxFrames = 10'000'000;

struct FramePlan {
  double fps = 30;
  std::int64_t frame_count = 1;
  // trajectory time per frame: speed / fps for times in seconds, speed for a table of rows
  double trajectory_step = 0;

  // The animation time of `frame`, in seconds.
  double Seconds(std::int64_t frame) const { return frame / fps; }
  // The trajectory time `frame` shows (seconds, or rows for a table without times).
  double TrajectoryTime(std::int64_t frame) const { return frame * trajectory_step; }
  // The camera yaw of `frame` for a turntable: `start_yaw` (radians) plus 2 pi * frame /
  // frame_count, one full turn over the animation that loops without a repeated frame.
  double TurntableYaw(std::int64_t frame, double start_yaw) const;
};

// The frames of `trajectory` played at `speed` (2 = twice as fast) and `fps` frames per second:
// T = trajectory.EndTime() / speed (a table without times: T = rows - 1 frames at speed 1).
// `duration_seconds`, when given, replaces T; past the trajectory's end its last pose holds.
// Throws Error for an fps, speed or duration that is not a positive finite number (fps at most
// kMaxFramesPerSecond), or more than kMaxFrames frames.
FramePlan PlanFrames(const Trajectory& trajectory, double fps, double speed,
                     std::optional<double> duration_seconds = {});

// The frames of a still pose shown for `duration_seconds` (a turntable without a trajectory); every
// frame samples trajectory time 0. Throws Error as PlanFrames does.
FramePlan PlanStill(double duration_seconds, double fps);

}  // namespace urdfsnap::motion
